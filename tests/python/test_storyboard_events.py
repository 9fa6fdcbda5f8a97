"""The storyboard's event log: order of events, names, reasons, signals, and the summary's activation counts."""

from __future__ import annotations

import json
from collections import Counter, defaultdict
from pathlib import Path

import pytest
from sbsim.runner import run
from sbsim_helpers import StoryRun, active_timeline, byte_key, run_story, write_story

ORDER_STORY = """
    import storyboard
    def createStories(board):
        # 0, unnamed: everyone between 100 s and 200 s (inclusive), with a signal
        board.registerStory(storyboard.Story(storyboard.TimeCondition(100, 200), [storyboard.SignalEffect("t")]))
        # 1, named: vehicles standing still; toggles often
        board.registerStory(storyboard.Story(storyboard.SpeedConditionLess(0.1), [], "halted"))
        # 2, unnamed: everyone from 150 s on, with a signal -> "story2" (its registration index)
        board.registerStory(storyboard.Story(storyboard.TimeCondition(150), [storyboard.SignalEffect("late")]))
        # 3, named
        board.registerStory(storyboard.Story(storyboard.CarSetCondition({"veh10", "veh2", "veh100", "veh7"}),
                                             [storyboard.SignalEffect("set")], name="fleet"))
"""
ORDER_NAMES = ["story0", "halted", "story2", "fleet"]


@pytest.fixture(scope="module")
def order_run(trips_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> StoryRun:
    return run_story(
        trips_cfg,
        ORDER_STORY,
        tmp_path_factory.mktemp("order"),
        fcd=True,
        sumo_options=(f"--tripinfo-output {tmp_path_factory.getbasetemp() / 'order-trip.xml'}",),
    )


def test_event_lines_have_the_documented_fields(order_run: StoryRun) -> None:
    lines = order_run.story.with_name("story.events.jsonl").read_text(encoding="utf-8").splitlines()
    assert lines
    for line in lines:
        e = json.loads(line)
        assert list(e)[:4] == ["t", "type", "story", "vehicle"], line
        assert isinstance(e["t"], (int, float)) and isinstance(e["vehicle"], str)
        if e["type"] == "activate":
            assert set(e) == {"t", "type", "story", "vehicle"}, line
        elif e["type"] == "deactivate":
            assert set(e) == {"t", "type", "story", "vehicle", "reason"}, line
            assert e["reason"] in ("condition", "vehicle_left"), line
        else:
            assert e["type"] == "signal", line
            assert set(e) == {"t", "type", "story", "vehicle", "cause", "others"}, line
            assert isinstance(e["others"], list)


def test_unnamed_stories_are_named_by_registration_index(order_run: StoryRun) -> None:
    names = {e["story"] for e in order_run.events}
    assert names == set(ORDER_NAMES)
    summary = order_run.result.summary()
    for name in ORDER_NAMES:
        assert f"activations {name}" in summary


def test_summary_activations_match_the_log(order_run: StoryRun) -> None:
    counts = Counter(e["story"] for e in order_run.events if e["type"] == "activate")
    summary = order_run.result.summary()
    for name in ORDER_NAMES:
        assert int(summary[f"activations {name}"]) == counts[name], name
    assert all(counts[name] > 0 for name in ORDER_NAMES), counts


def test_time_is_sumo_time_after_the_step_and_never_decreases(order_run: StoryRun) -> None:
    times = [float(e["t"]) for e in order_run.events]
    assert times == sorted(times)
    assert all(t == int(t) for t in times), "step length is 1 s: every event is at a whole second"
    assert 1 <= times[0] and times[-1] <= 300


def test_events_within_a_step_are_ordered(order_run: StoryRun) -> None:
    """Per step: vehicle_left deactivations first (vehicles ascending, stories in registration order),
    then the evaluation pass (vehicles ascending by byte order, stories in registration order), with
    each signal right after its activation."""
    index = {name: i for i, name in enumerate(ORDER_NAMES)}
    by_time: dict[float, list[dict]] = defaultdict(list)
    for e in order_run.events:
        by_time[float(e["t"])].append(e)
    saw_left_and_evaluation = False
    for t, events in by_time.items():
        left = [e for e in events if e.get("reason") == "vehicle_left"]
        assert events[: len(left)] == left, f"t={t}: vehicle_left deactivations must come first"
        keys = [(byte_key(e["vehicle"]), index[e["story"]]) for e in left]
        assert keys == sorted(keys), f"t={t}: vehicle_left order {keys}"
        rest = events[len(left) :]
        saw_left_and_evaluation |= bool(left) and bool(rest)
        keys = []
        for i, e in enumerate(rest):
            if e["type"] == "signal":
                prev = rest[i - 1]
                assert (
                    i > 0
                    and prev["type"] == "activate"
                    and prev["vehicle"] == e["vehicle"]
                    and prev["story"] == e["story"]
                ), f"t={t}: signal not right after its activation: {e}"
                continue
            keys.append((byte_key(e["vehicle"]), index[e["story"]]))
        assert keys == sorted(keys), f"t={t}: evaluation order {[(k[0].decode(), k[1]) for k in keys]}"
        assert len(set(keys)) == len(keys), f"t={t}: a story changed twice for one vehicle"
    assert saw_left_and_evaluation, "the scenario should have steps with both kinds"


def test_signal_follows_every_activation_of_a_story_with_a_signal_effect(order_run: StoryRun) -> None:
    events = order_run.events
    causes = {"story0": "t", "story2": "late", "fleet": "set"}
    for i, e in enumerate(events):
        if e["type"] == "activate" and e["story"] in causes:
            nxt = events[i + 1]
            assert nxt == {
                "t": e["t"],
                "type": "signal",
                "story": e["story"],
                "vehicle": e["vehicle"],
                "cause": causes[e["story"]],
                "others": [],
            }
        if e["type"] == "activate" and e["story"] == "halted":
            assert i + 1 == len(events) or events[i + 1]["type"] != "signal"
    assert len(order_run.of(type="signal")) == sum(len(order_run.of(type="activate", story=s)) for s in causes)


def test_time_condition_is_inclusive_and_covers_every_running_vehicle(order_run: StoryRun) -> None:
    fcd = order_run.fcd
    assert fcd is not None
    timeline = active_timeline(order_run.events, "story0", fcd.times)
    for t in fcd.times:
        expected = fcd.running[t] if 100 <= t <= 200 else set()
        assert timeline[t] == expected, f"t={t}"
    assert {e["t"] for e in order_run.of(type="activate", story="story0")} >= {100}
    assert min(e["t"] for e in order_run.of(type="activate", story="story0")) == 100
    ends = order_run.of(type="deactivate", story="story0", reason="condition")
    assert ends and {e["t"] for e in ends} == {201}
    # TimeCondition without an end stays true to the end of the run.
    late = active_timeline(order_run.events, "story2", fcd.times)
    assert all(late[t] == (fcd.running[t] if t >= 150 else set()) for t in fcd.times)


def test_vehicle_left_ends_the_active_stories_of_arrived_vehicles(
    order_run: StoryRun, tmp_path_factory: pytest.TempPathFactory
) -> None:
    import xml.etree.ElementTree as ET

    fcd = order_run.fcd
    assert fcd is not None
    left = order_run.of(type="deactivate", reason="vehicle_left")
    assert left
    # Each vehicle_left comes at the first step the vehicle is no longer running, for each story active then.
    trips = {
        t.attrib["id"]: float(t.attrib["arrival"])
        for t in ET.parse(tmp_path_factory.getbasetemp() / "order-trip.xml").getroot().iter("tripinfo")
    }
    for e in left:
        v, t = e["vehicle"], float(e["t"])
        assert v not in fcd.running[t] and v in fcd.running[t - 1], e
        assert trips[v] + 1 == t, f"{v} arrived at SUMO time {trips[v]} (sbsim {trips[v] + 1}), left at {t}"
    # Every vehicle that arrives while a story is active for it gets vehicle_left for that story.
    for story in ("story0", "story2"):
        timeline = active_timeline(order_run.events, story, fcd.times)
        expected = {(v, a + 1) for v, a in trips.items() if v in timeline.get(a, ())}
        got = {(e["vehicle"], float(e["t"])) for e in left if e["story"] == story}
        assert got == expected, story
    # A vehicle that left is never seen again.
    last = {}
    for e in order_run.events:
        last.setdefault(e["vehicle"], []).append(e)
    for v, events in last.items():
        lefts = [i for i, e in enumerate(events) if e.get("reason") == "vehicle_left"]
        if lefts:
            assert all(e.get("reason") == "vehicle_left" for e in events[lefts[0] :]), v
            assert len({e["t"] for e in events[lefts[0] :]}) == 1, v


def test_car_set_condition(order_run: StoryRun) -> None:
    fcd = order_run.fcd
    assert fcd is not None
    fleet = {"veh10", "veh2", "veh100", "veh7"}
    timeline = active_timeline(order_run.events, "fleet", fcd.times)
    for t in fcd.times:
        assert timeline[t] == fcd.running[t] & fleet, f"t={t}"
    assert set(order_run.activated("fleet")) == fleet
    assert order_run.result.summary()["activations fleet"] == "4"


def test_speed_condition_less_is_strict_and_follows_sumo(order_run: StoryRun) -> None:
    fcd = order_run.fcd
    assert fcd is not None
    timeline = active_timeline(order_run.events, "halted", fcd.times)
    checked = 0
    for t in fcd.times:
        for v in fcd.running[t]:
            speed = fcd.speed[v][t]
            if abs(speed - 0.1) < 1e-5:
                continue
            assert (v in timeline[t]) == (speed < 0.1), f"{v} at t={t}, speed {speed}"
            checked += speed < 0.1
    assert checked > 50


def test_events_without_a_story_file_is_empty(trips_cfg: Path, tmp_path: Path) -> None:
    from sbsim.runner import run

    events = tmp_path / "ev.jsonl"
    events.write_text("stale\n")
    result = run(trips_cfg, events=events, end=20)
    assert result.returncode == 0, result.stderr
    assert events.read_text() == ""


def test_story_names_are_json_escaped(trips_cfg: Path, tmp_path: Path) -> None:
    run = run_story(
        trips_cfg,
        r"""
        import storyboard
        def createStories(board):
            board.registerStory(storyboard.Story(storyboard.CarSetCondition("veh1"),
                                                 [storyboard.SignalEffect('say "hi"\n\u00e9')], 'quo"te\\back'))
    """,
        tmp_path,
        end=20,
    )
    assert run.of(type="activate") == [
        {"t": run.events[0]["t"], "type": "activate", "story": 'quo"te\\back', "vehicle": "veh1"}
    ]
    assert run.of(type="signal")[0]["cause"] == 'say "hi"\n\u00e9'


def test_times_are_exact_with_a_fractional_step(trips_cfg: Path, tmp_path: Path) -> None:
    run = run_story(
        trips_cfg,
        """
        import storyboard, timeline
        def createStories(board):
            board.registerStory(storyboard.Story(
                storyboard.AndCondition(storyboard.CarSetCondition("veh0"),
                                        storyboard.TimeCondition(timeline.milliseconds(1250), 1.55)), [], "window"))
            board.registerStory(storyboard.Story(
                storyboard.AndCondition(storyboard.CarSetCondition("veh0"), storyboard.TimeCondition(0.3, 0.3)),
                [], "instant"))
    """,
        tmp_path,
        end=3,
        sumo_options=("--step-length 0.1",),
    )
    text = run.story.with_name("story.events.jsonl").read_text()
    assert text.splitlines() == [
        '{"t":0.3,"type":"activate","story":"instant","vehicle":"veh0"}',
        '{"t":0.4,"type":"deactivate","story":"instant","vehicle":"veh0","reason":"condition"}',
        '{"t":1.3,"type":"activate","story":"window","vehicle":"veh0"}',
        '{"t":1.6,"type":"deactivate","story":"window","vehicle":"veh0","reason":"condition"}',
    ]
    assert run.result.summary()["steps"] == "30"


def test_create_stories_runs_once_before_the_first_step(trips_cfg: Path, tmp_path: Path) -> None:
    log = tmp_path / "calls.txt"
    run = run_story(
        trips_cfg,
        f"""
        import numpy as np
        import storyboard

        def note(text):
            with open({str(log)!r}, "a") as f:
                f.write(text + "\\n")

        class Steps(storyboard.Condition):
            def test_all(self, snapshot):
                note(f"step {{snapshot.time:g}} {{len(snapshot)}}")
                return np.zeros(len(snapshot), dtype=bool)

        note("module")

        def createStories(board):
            note("create")
            board.registerStory(storyboard.Story(Steps(), []))
    """,
        tmp_path,
        end=55,
        sumo_options=("--begin 50",),
    )
    lines = log.read_text().splitlines()
    assert lines[:2] == ["module", "create"]
    steps = [line.split() for line in lines[2:]]
    assert [float(s[1]) for s in steps] == [float(t) for t in range(51, 56)]
    assert all(s[0] == "step" for s in steps)
    assert run.result.summary()["steps"] == "5"


def test_event_log_reads_into_pandas(trips_cfg: Path, tmp_path: Path) -> None:
    pandas = pytest.importorskip("pandas")
    story = write_story(
        tmp_path,
        """
        import storyboard

        def createStories(board):
            fast = storyboard.SpeedConditionGreater(5)
            board.registerStory(storyboard.Story(fast, [storyboard.SignalEffect("fast")]))
        """,
    )
    events = tmp_path / "events.jsonl"
    result = run(trips_cfg, story=story, events=events, end=60)
    assert result.returncode == 0, result.stderr
    frame = pandas.read_json(events, lines=True)
    assert {"t", "type", "story", "vehicle"} <= set(frame.columns)
    assert set(frame["type"]) == {"activate", "deactivate", "signal"}
    assert (frame["type"] == "activate").sum() == int(result.summary()["activations story0"])
