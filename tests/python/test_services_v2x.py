"""Artery's CA and DEN services end to end, on the motorway-accident scenario.

The crash car's story signals "accident"; its DEN service's StoryboardEvent use case sends a DENM
(cause 2) every second; a DenmCondition story caps every vehicle whose DENM memory holds it at
15 m/s. A TractionLoss variant checks the repetition and the geo-broadcast area (with a radio
range beyond the area). Checked against the event log, the DENM trace and SUMO's FCD output.
"""

from __future__ import annotations

import math
from pathlib import Path

from sbsim.messages import read_message_lines
from sbsim.runner import RunResult, read_events, run
from sbsim_helpers import STORIES, FcdTrace, assert_bad_input, assert_no_crash, message_counts, read_fcd, write_story

SCENARIO = STORIES / "motorway-accident"
STEP = 0.5  # motorway.sumocfg
CAP = 15.0  # story.py: SpeedEffect(15.0)


def read_denm(path: Path) -> list[dict]:
    """The DENM phase lines of a message trace (its tx, rx and lost lines left out)."""
    return [line for line in read_message_lines(path) if line["event"] == "denm"]


def fcd_heard(denm: list[dict], fcd: FcdTrace) -> list[tuple[str, float]]:
    """(station, FCD step) of each vehicle's first DENM memory entry, where the FCD has it."""
    out = []
    for d in denm:
        if d["phase"] == "new" and d["station"] != "crash":
            step = round(math.ceil(d["t"] / STEP) * STEP, 3)
            if step in fcd.pos.get(d["station"], {}):
                out.append((d["station"], step))
    return out


def run_motorway(
    tmp_path: Path, story: Path, services: Path, *extra: str
) -> tuple[RunResult, list[dict], FcdTrace, list[dict]]:
    events, fcd, denm = tmp_path / "events.jsonl", tmp_path / "fcd.xml", tmp_path / "messages.jsonl"
    result = run(
        SCENARIO / "motorway.sumocfg",
        story=story,
        events=events,
        sumo_options=[f"--fcd-output {fcd}", "--precision 3"],
        extra=["--services", str(services), "--messages", str(denm), *extra],
        timeout=300,
    )
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    return result, read_events(events), read_fcd(fcd, step=STEP), read_denm(denm)


def test_denm_condition_caps_exactly_the_warned_vehicles(tmp_path: Path) -> None:
    result, events, fcd, denm = run_motorway(tmp_path, SCENARIO / "story.py", SCENARIO / "services.xml")
    sent = [d for d in denm if d["station"] == "crash"]
    # Sent at the crash car's first trigger after the signal at 40 s (its own clock), cancelled at once.
    assert [(d["phase"], d["action"]) for d in sent] == [("new", "crash:1"), ("terminate", "crash:1")]
    assert 40 < sent[0]["t"] <= 40.1
    assert sent[1]["t"] == 160.5
    new = {d["station"]: d["t"] for d in denm if d["phase"] == "new" and d["station"] != "crash"}
    terminated = {d["station"] for d in denm if d["phase"] == "terminate" and d["station"] != "crash"}
    assert len(new) > 50
    # Exactly the vehicles that heard the DENM were capped by the story, none other.
    capped = {e["vehicle"] for e in events if e["story"] == "warned" and e["type"] == "activate"}
    assert capped == set(new)
    # Every receiver in radio range (500 m) of the cancellation dropped the event; those further
    # away keep it until it expires, as they would on a road.
    crash_then = fcd.pos["crash"][160.5]
    in_range = {v for v in new if 160.5 in fcd.pos[v] and math.dist(fcd.pos[v][160.5], crash_then) < 490}
    assert in_range and in_range <= terminated <= set(new)
    # Capped: from 8 s after the warning (braking from 36 m/s) to the end of the event.
    for vehicle, t in new.items():
        late = fcd.speeds(vehicle, t + 8, 160)
        assert all(v <= CAP + 0.1 for v in late.values()), (vehicle, max(late.values(), default=0))
    crash_x = fcd.pos["crash"][45.0][0]
    before = [
        v for v, t in new.items() if fcd.pos[v].get(round(math.ceil(t / STEP) * STEP, 3), (math.inf, 0))[0] < crash_x
    ]
    print(f"warned: {len(new)} vehicles, {len(before)} of them before reaching the accident at x = {crash_x:.0f} m")
    assert len(before) > 30
    # The story ends at the first step after 160 s: sent every second from just after 40 s to just
    # after 160 s, then the cancellation.
    assert message_counts(result.stdout)["DENM"][0] == 122


def test_traction_loss_repeats_every_second_and_stays_in_its_area(tmp_path: Path) -> None:
    (tmp_path / "uc.xml").write_text(
        '<usecases><usecase type="artery.application.den.TractionLoss"><filters><name pattern="crash"/>'
        "</filters></usecase></usecases>"
    )
    services = tmp_path / "services.xml"
    services.write_text(
        '<services><service type="artery.application.CaService"/>'
        '<service type="artery.application.DenService" useCases="uc.xml"><listener port="2002"/></service>'
        "</services>"
    )
    story = write_story(
        tmp_path,
        "from storyboard import *\n"
        "def createStories(board):\n"
        "    slip = AndCondition(CarSetCondition('crash'), TimeCondition(40))\n"
        "    board.registerStory(Story(slip, [SignalEffect('traction loss')], name='slip'))\n",
    )
    # A radio range beyond the 1,000 m area: only the area keeps the DENM from stations further out.
    result, _, fcd, denm = run_motorway(tmp_path, story, services, "--end", "70", "--v2x-range", "1800")
    assert "Artery's <listener> ignored" in result.stderr
    sent, delivered = message_counts(result.stdout)["DENM"]
    assert sent in (30, 31)  # every second from 40 s to the end at 70 s
    new = {d["station"]: d["t"] for d in denm if d["phase"] == "new" and d["station"] != "crash"}
    assert {d["cause"] for d in denm} == {6}
    centre = fcd.pos["crash"][40.0]
    far = 0
    for vehicle, positions in fcd.pos.items():
        if vehicle == "crash" or 40.0 not in positions:
            continue
        distance = math.dist(positions[40.0], centre)
        if distance <= 990:
            assert vehicle in new, (vehicle, distance)
        elif 1010 < distance <= 1700:
            far += 1
            # Outside the area but in radio range: it may enter the area later and hear a repetition.
            if vehicle in new:
                t = new[vehicle]
                here = fcd.pos[vehicle][round(math.ceil(t / STEP) * STEP, 3)]
                # The area stays where the event was detected, whatever the sender does since.
                assert math.dist(here, centre) <= 1000 + 20
    assert far > 5, "some vehicles were in radio range but outside the area"


def police_services(tmp_path: Path, police_type: str) -> Path:
    """A services file in the form of Artery's highway-police ones (with their <listener> ports)."""
    path = tmp_path / f"{police_type}.xml"
    path.write_text(
        f'<services><service type="{police_type}"><listener port="8001"/>'
        '<filters><name pattern="police0"/></filters></service>'
        '<service type="ClearLaneService"><listener port="8001"/>'
        '<filters><name pattern="police0" match="inverse"/></filters></service></services>'
    )
    return path


def test_artery_police_services_keep_their_meanings(tmp_path: Path) -> None:
    highway = STORIES / "highway-police"
    counts = {}
    for police_type in ("PoliceService", "PoliceServiceStoryboard"):
        for story in (None, highway / "story.py"):
            result = run(
                highway / "highway.sumocfg",
                story=story,
                end=20,
                extra=["--services", str(police_services(tmp_path, police_type))],
                timeout=120,
            )
            assert result.returncode == 0, result.stderr
            counts[police_type, story is not None] = message_counts(result.stdout).get("ClearLane", (0, 0))[0]
    # PoliceService broadcasts from its departure (6 s) on, every 0.1 s, story or not.
    assert counts["PoliceService", False] == counts["PoliceService", True] >= 120
    # PoliceServiceStoryboard waits for the story's "siren on" at 10 s.
    assert counts["PoliceServiceStoryboard", False] == 0
    assert 90 <= counts["PoliceServiceStoryboard", True] < counts["PoliceService", True]


def test_cam_condition_sees_the_neighbours_a_vehicle_heard_of(tmp_path: Path) -> None:
    story = write_story(
        tmp_path,
        "from storyboard import *\n"
        "def createStories(board):\n"
        "    close = CamCondition(distance=20, max_age=0.5)\n"
        "    board.registerStory(Story(close, [SignalEffect('close')], name='close'))\n",
    )
    services = tmp_path / "ca.xml"
    services.write_text('<services><service type="CaService"/></services>')
    _, events, fcd, _ = run_motorway(tmp_path, story, services, "--end", "60")
    activations = [e for e in events if e["story"] == "close" and e["type"] == "activate"]
    assert len(activations) > 10
    for e in activations:
        t, ego = e["t"], e["vehicle"]
        here = fcd.pos[ego][t]
        # A CAM at most 0.5 s old put some other vehicle within 20 m: it is within 20 m plus what
        # both drove since (at most 0.5 s at 36 m/s each) now.
        nearest = min(math.dist(here, p[t]) for v, p in fcd.pos.items() if v != ego and t in p)
        assert nearest <= 20 + 36, (ego, t, nearest)
    # Without the CA service nobody heard anything: never true.
    empty = tmp_path / "none.xml"
    empty.write_text('<services><service type="DenService"/></services>')
    _, events, _, _ = run_motorway(tmp_path, story, empty, "--end", "60")
    assert not [e for e in events if e["story"] == "close"]


def test_bad_use_case_files_are_one_line_naming_file_and_line(tmp_path: Path) -> None:
    services = tmp_path / "services.xml"
    services.write_text('<services>\n<service type="artery.application.DenService" useCases="uc.xml"/>\n</services>')
    cases = {
        '<usecases>\n<usecase type="artery.application.den.Skid"/>\n</usecases>': [
            "uc.xml:2",
            "unknown DEN use case 'Skid'",
        ],
        '<usecases>\n\n<usecase type="StoryboardEvent" cause="2"/>\n</usecases>': ["uc.xml:3", "'signal'"],
        "<usecases><usecase/></usecases>": ["uc.xml:1", "no 'type'"],
        "<cases/>": ["uc.xml:1", "root element must be <usecases>"],
    }
    for text, needles in cases.items():
        (tmp_path / "uc.xml").write_text(text)
        result = run(SCENARIO / "motorway.sumocfg", end=5, extra=["--services", str(services)], timeout=60)
        assert_bad_input(result, "--services", *needles)
    (tmp_path / "uc.xml").unlink()
    result = run(SCENARIO / "motorway.sumocfg", end=5, extra=["--services", str(services)], timeout=60)
    assert_bad_input(result, "uc.xml", "cannot read")


def test_denm_condition_ahead_caps_only_the_vehicles_driving_towards_the_event(tmp_path: Path) -> None:
    # The event 'ahead' within 800 m: of the warned, only those still before the crash car (the
    # motorway runs east, +x) take the cap; those past it heard the DENM but are not capped.
    story = write_story(
        tmp_path,
        """
        from storyboard import *
        def createStories(board):
            accident = AndCondition(CarSetCondition('crash'), TimeCondition(40, 160))
            board.registerStory(Story(accident, [StopEffect(), SignalEffect('accident', 'accident over')],
                                      name='accident'))
            ahead = DenmCondition(cause=2, within=800, ahead=True)
            board.registerStory(Story(ahead, [SpeedEffect(15.0)], name='warned'))
        """,
    )
    _, events, fcd, denm = run_motorway(tmp_path, story, SCENARIO / "services.xml", "--end", "80")
    heard = {d["station"] for d in denm if d["phase"] == "new" and d["station"] != "crash"}
    activations = [(e["vehicle"], e["t"]) for e in events if e["story"] == "warned" and e["type"] == "activate"]
    assert activations and {v for v, _ in activations} < heard
    # The event is where the crash car was when its DENM went out (~40 s; it stops some 50 m on):
    # forwarded through the 1,000 m area, the DENM reaches vehicles beyond 800 m too, which the
    # condition leaves out (one step's travel, 18 m, of slack for the positions' times).
    event = fcd.pos["crash"][40.0]
    for vehicle, t in activations:
        x = fcd.pos[vehicle][t][0]
        assert x < event[0] and math.dist(fcd.pos[vehicle][t], event) <= 800 + 18, (vehicle, t, x, event)
    assert any(math.dist(fcd.pos[v][t], event) > 820 for v, t in fcd_heard(denm, fcd)), "heard beyond 800 m too"
