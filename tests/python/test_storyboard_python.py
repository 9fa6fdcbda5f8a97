"""The Python side of stories: custom conditions and effects, the snapshot arrays, Artery scripts unmodified."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from sbsim_helpers import StoryRun, assert_active_as_predicted, byte_key, run_story


def _types(cfg: Path) -> dict[str, str]:
    root = ET.parse(cfg.parent / "routes.rou.xml").getroot()
    return {v.attrib["id"]: v.attrib["type"] for v in root.iter("vehicle")}


CUSTOM_STORY = """
    import json
    import numpy as np
    import storyboard

    class IsTruck(storyboard.Condition):
        def test(self, vehicle):
            return vehicle.type == "truck"

    class WestOf(storyboard.Condition):
        '''Vectorised: the vehicles with SUMO x below a limit.'''
        def __init__(self, x):
            super().__init__()
            self.x = x
        def test_all(self, snapshot):
            positions = np.asarray(snapshot.positions)
            assert positions.shape == (len(snapshot), 2)
            return positions[:, 0] < self.x

    class Fast(storyboard.Condition):
        def test_all(self, snapshot):
            return np.asarray(snapshot.speeds) > 9.0

    class Shape(storyboard.Condition):
        '''Checks the snapshot's arrays once per step and records its ids; never true.'''
        def test_all(self, snapshot):
            n = len(snapshot)
            ids = list(snapshot.ids)
            for name in ("speeds", "angles", "accelerations", "lengths", "widths", "max_speeds"):
                column = getattr(snapshot, name)
                assert column.shape == (n,), (name, column.shape)
            with open({ids_log!r}, "a") as f:
                f.write(json.dumps([snapshot.time, ids, [float(x) for x in snapshot.lengths]]) + "\\n")
            return np.zeros(n, dtype=bool)

    class Cap(storyboard.Effect):
        '''A custom effect through the VehicleController.'''
        def __init__(self, mps):
            super().__init__()
            self.mps = mps
            self.before = {{}}
        def apply(self, vehicle):
            self.before[vehicle.id] = vehicle.max_speed
            vehicle.set_max_speed(self.mps)
            self.log("apply", vehicle)
        def remove(self, vehicle):
            vehicle.set_max_speed(self.before.pop(vehicle.id))
            self.log("remove", vehicle)
        def log(self, what, vehicle):
            with open({effect_log!r}, "a") as f:
                f.write(json.dumps([what, vehicle.id, vehicle.type_id, vehicle.max_speed]) + "\\n")

    def createStories(board):
        board.registerStory(storyboard.Story(Shape(), [], "shape"))
        board.registerStory(storyboard.Story(IsTruck(), [storyboard.SignalEffect("truck")], "trucks"))
        board.registerStory(storyboard.Story(WestOf(300.0), [], "west"))
        board.registerStory(storyboard.Story(storyboard.AndCondition(Fast(), storyboard.TimeCondition(0, 100)),
                                             [], "fast_early"))
        board.registerStory(storyboard.Story(
            storyboard.AndCondition(storyboard.CarSetCondition(["veh11", "veh23"]), storyboard.TimeCondition(60, 150)),
            [Cap(3.0)], "custom_cap"))
"""


@pytest.fixture(scope="module")
def custom_run(loops_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> tuple[StoryRun, Path, Path]:
    d = tmp_path_factory.mktemp("custom")
    ids_log, effect_log = d / "ids.jsonl", d / "effect.jsonl"
    run = run_story(
        loops_cfg, CUSTOM_STORY.format(ids_log=str(ids_log), effect_log=str(effect_log)), d, end=220, fcd=True
    )
    return run, ids_log, effect_log


def test_custom_condition_returning_bool(custom_run: tuple[StoryRun, Path, Path], loops_cfg: Path) -> None:
    run, _, _ = custom_run
    types = _types(loops_cfg)
    trucks = {v for v, t in types.items() if t == "truck"}
    assert trucks
    assert set(run.activated("trucks")) == trucks
    assert len(run.activated("trucks")) == len(trucks)
    assert all(e["others"] == [] for e in run.of(type="signal", story="trucks"))


def test_vectorised_condition_over_positions(custom_run: tuple[StoryRun, Path, Path]) -> None:
    run, _, _ = custom_run
    fcd = run.fcd
    assert fcd is not None
    n = assert_active_as_predicted(
        run, "west", lambda v, t: fcd.pos[v][t][0] < 300, ambiguous=lambda v, t: abs(fcd.pos[v][t][0] - 300) < 1e-3
    )
    assert n > 100


def test_vectorised_condition_over_speeds_in_a_tree(custom_run: tuple[StoryRun, Path, Path]) -> None:
    run, _, _ = custom_run
    fcd = run.fcd
    assert fcd is not None
    n = assert_active_as_predicted(
        run,
        "fast_early",
        lambda v, t: t <= 100 and fcd.speed[v][t] > 9.0,
        ambiguous=lambda v, t: abs(fcd.speed[v][t] - 9.0) < 1e-4,
    )
    assert n > 20


def test_snapshot_ids_are_the_running_vehicles_in_byte_order(custom_run: tuple[StoryRun, Path, Path]) -> None:
    run, ids_log, _ = custom_run
    fcd = run.fcd
    assert fcd is not None
    rows = [json.loads(line) for line in ids_log.read_text().splitlines()]
    assert [t for t, _, _ in rows] == fcd.times
    for t, ids, lengths in rows:
        assert ids == sorted(fcd.running[t], key=byte_key), t
        assert set(lengths) <= {4.5, 12.0}


def test_custom_effect_is_applied_removed_and_obeyed(custom_run: tuple[StoryRun, Path, Path], loops_cfg: Path) -> None:
    run, _, effect_log = custom_run
    types = _types(loops_cfg)
    calls = [json.loads(line) for line in effect_log.read_text().splitlines()]
    original = {"car": 50.0, "truck": 25.0}
    expected = []
    for e in run.events:
        if e["story"] == "custom_cap" and e["type"] != "signal":
            v = e["vehicle"]
            if e["type"] == "activate":
                expected.append(["apply", v, types[v], 3.0])
            else:
                expected.append(["remove", v, types[v], original[types[v]]])
    # SUMO gives a vehicle its own copy of its type ("car@veh11") once one of its type's values changes.
    assert [[what, v, vtype.split("@")[0], m] for what, v, vtype, m in calls] == expected
    assert [c[1] for c in calls if c[0] == "apply"] == ["veh11", "veh23"]
    fcd = run.fcd
    assert fcd is not None
    for v in ("veh11", "veh23"):
        during = fcd.speeds(v, 66, 150)
        assert len(during) == 85 and max(during.values()) <= 3.05, (v, max(during.values()))
    assert any(max(fcd.speeds(v, 152, 220).values()) > 6 for v in ("veh11", "veh23"))


def test_custom_condition_returning_a_set_gives_the_signal_its_others(trips_cfg: Path, tmp_path: Path) -> None:
    run = run_story(
        trips_cfg,
        """
        import storyboard

        class Neighbours(storyboard.Condition):
            def test(self, vehicle):
                if vehicle.id not in ("veh3", "veh4") or vehicle.time < 30:
                    return False
                return {"veh20", "veh3", "veh100000", "veh1", "veh10", "veh4"}

        def createStories(board):
            board.registerStory(storyboard.Story(Neighbours(), [storyboard.SignalEffect("near")], "near"))
    """,
        tmp_path,
        end=40,
    )
    signals = {e["vehicle"]: e["others"] for e in run.of(type="signal")}
    # Running at 30 s: veh0 .. veh14; ids not running are dropped, the ego too; byte order.
    assert signals == {"veh3": ["veh1", "veh10", "veh4"], "veh4": ["veh1", "veh10", "veh3"]}


def test_pythonic_helpers_and_aliases(trips_cfg: Path, tmp_path: Path) -> None:
    run = run_story(
        trips_cfg,
        """
        import storyboard
        from storyboard import all_of, any_of, seconds, milliseconds

        def createStories(board):
            rng = board.random_generator(0)
            assert rng.index == 0 and 0 <= rng.uniform() < 1 and 5 <= rng.uniform(5, 6) < 6
            assert board.getWarmupEndTime() == storyboard.SimTime(0)
            assert seconds(1.5) == milliseconds(1500) == storyboard.SimTime(1.5)
            assert float(seconds(2) + 1) == 3.0
            board.register_story(storyboard.Story(
                all_of(storyboard.TimeCondition(seconds(20)), storyboard.CarSetCondition("veh1"),
                       storyboard.SpeedConditionGreater(-1)),
                [storyboard.StopEffectFactory()], name="all"))
            board.register_story(storyboard.Story(
                any_of(storyboard.CarSetCondition("veh2"), storyboard.CarSetCondition("veh3")),
                [storyboard.SignalEffectFactory("any")], name="any"))
            assert [s.name for s in board.stories] == ["all", "any"]
    """,
        tmp_path,
        end=40,
    )
    assert run.of(type="activate", story="all") == [{"t": 20, "type": "activate", "story": "all", "vehicle": "veh1"}]
    assert set(run.activated("any")) == {"veh2", "veh3"}


REGISTER = "storyboard.Story(storyboard.CarSetCondition('veh1'), [storyboard.StopEffect()], name='ok')"


@pytest.mark.parametrize(
    "create",
    [
        f"def createStories():\n    board.registerStory({REGISTER})",  # Artery: the module-level board
        f"def createStories(b):\n    b.registerStory({REGISTER})",
        f"def createStories(*args):\n    args[0].registerStory({REGISTER})",
        f"def createStories(b=None, *, k=1):\n    b.registerStory({REGISTER})",
        f"class Create:\n    def __call__(self, b):\n        b.registerStory({REGISTER})\ncreateStories = Create()",
    ],
)
def test_create_stories_is_given_the_board_when_it_takes_a_parameter(
    create: str, trips_cfg: Path, tmp_path: Path
) -> None:
    run = run_story(trips_cfg, f"import storyboard\n{create}\n", tmp_path, end=10)
    assert run.activated("ok") == ["veh1"]


def test_create_stories_taking_only_keywords_is_a_clear_error(trips_cfg: Path, tmp_path: Path) -> None:
    run = run_story(trips_cfg, "def createStories(**kw):\n    pass\n", tmp_path, end=10, check=False)
    assert run.returncode == 2
    assert "TypeError" in run.result.stderr and "story.py" in run.result.stderr


def test_a_condition_declaring_its_columns_reads_those_and_no_others(trips_cfg: Path, tmp_path: Path) -> None:
    # The snapshot reads only what the conditions declared: a declared column is there, another
    # one is a clear error (not a stale value), a wrong declaration is bad input.
    story = """
        import storyboard

        class Slow(storyboard.Condition):
            columns = ("speed",)
            def test(self, vehicle):
                return vehicle.time >= 10 and vehicle.speed < {limit} and {extra}

        def createStories(board):
            board.registerStory(storyboard.Story(Slow(), [storyboard.SignalEffect("slow")], "slow"))
    """
    run = run_story(trips_cfg, story.format(limit=100, extra="True"), tmp_path / "declared", end=20)
    assert run.activated("slow"), "speed was declared: the condition sees it"

    run = run_story(
        trips_cfg, story.format(limit=100, extra="vehicle.lane != ''"), tmp_path / "undeclared", end=20, check=False
    )
    assert run.returncode == 2
    assert "holds no 'lane' in this run" in run.result.stderr

    wrong = story.replace('("speed",)', '("speed", "colour")').format(limit=1, extra="True")
    run = run_story(trips_cfg, wrong, tmp_path / "wrong", end=20, check=False)
    assert run.returncode == 2
    assert "Slow.columns must be a sequence of column names" in run.result.stderr
    assert "story.py:" in run.result.stderr


ARTERY_DEMO = """\
#!/usr/bin/env python

# reference variable to Storyboard Omnet++ module: board
import storyboard
import timeline

print ("demo.py successfully imported...")

def createStories():
\t# Create coordinates needed for the PolygonCondition
\tcoord0 = storyboard.Coord(0.0, 0.0)
\tcoord1 = storyboard.Coord(3000.0, 0.0)
\tcoord2 = storyboard.Coord(3000.0, 1600.0)
\tcoord3 = storyboard.Coord(0.0, 1600.0)

\t# Create PolygonCondition
\tcond0 = storyboard.PolygonCondition([coord0, coord1, coord2, coord3])

\t# Create TimeCondition
\tcond1 = storyboard.TimeCondition(timeline.milliseconds(15000))

\t# Create CarSetCondition
\tcond2 = storyboard.CarSetCondition(["veh1", "veh3", "veh5"])

\t# Create SpeedEffectFactory
\teffectFactory0 = storyboard.SpeedEffectFactory(2.44)

\t# Create AndConditions
\tand0 = storyboard.AndCondition(cond0, cond1)
\tand1 = storyboard.AndCondition(and0, cond2)

\t# Create OrCondition
\tcond3 = storyboard.TimeCondition(timeline.seconds(190))
\tor0 = storyboard.OrCondition(cond3, and1)

\t# Create Story
\tstory = storyboard.Story(or0, [effectFactory0])

\t# Create Story 2
\tcond4 = storyboard.TimeCondition(timeline.seconds(50), timeline.seconds(60))
\teffectFactory1 = storyboard.SpeedEffectFactory(2.44)
\tstory1 = storyboard.Story(cond4, [effectFactory1])

\t# Create Story 3, overlapping story0
\tcond5 = storyboard.TimeCondition(timeline.seconds(200), timeline.seconds(210))
\tcond6 = storyboard.CarSetCondition(["veh0", "veh2"])
\tand2 = storyboard.AndCondition(cond5, cond6)
\teffectFactory2 = storyboard.SpeedEffectFactory(0.1)
\tstory2 = storyboard.Story(and2, [effectFactory2])

\t# Create Story 4, SpeedConditionGreater
\tcond7 = storyboard.SpeedConditionGreater(4.0)
\tcond8 = storyboard.TimeCondition(storyboard.SimTime(20), timeline.seconds(30))
\tand3 = storyboard.AndCondition(cond7, cond8)
\teffectFactory3 = storyboard.SpeedEffectFactory(1.0)
\tstory3 = storyboard.Story(and3, [effectFactory3])

\t# Register Stories at the Storyboard
\tboard.registerStory(story)
\tboard.registerStory(story1)
\tboard.registerStory(story2)
\tboard.registerStory(story3)

\tprint("Stories loaded!")
"""


def test_artery_demo_script_runs_unmodified(loops_cfg: Path, tmp_path: Path) -> None:
    # Artery's scenarios/storyboard/demo.py with this scenario's vehicle ids (tabs, prints, global board).
    ids = {"veh1": "veh01", "veh3": "veh03", "veh5": "veh05", "veh0": "veh00", "veh2": "veh02"}
    source = ARTERY_DEMO
    for old, new in ids.items():
        source = source.replace(f'"{old}"', f'"{new}"')
    run = run_story(loops_cfg, source, tmp_path, end=230, fcd=True, name="demo.py")
    out = run.result.stdout
    assert "demo.py successfully imported..." in out and "Stories loaded!" in out
    assert out.index("Stories loaded!") < out.index("steps:")
    s = run.result.summary()
    assert {k for k in s if k.startswith("activations")} == {f"activations story{i}" for i in range(4)}
    fcd = run.fcd
    assert fcd is not None
    location = ET.parse(loops_cfg.parent / "net.net.xml").getroot().find("location")
    assert location is not None
    xmin, _, _, ymax = (float(c) for c in location.attrib["convBoundary"].split(","))

    def in_canvas_polygon(v: str, t: float) -> bool:
        x, y = fcd.pos[v][t]
        return 0 < x - xmin < 3000 and 0 < ymax - y < 1600

    def on_edge(v: str, t: float) -> bool:
        x, y = fcd.pos[v][t]
        return min(abs(x - xmin), abs(ymax - y)) < 1e-3

    listed = {"veh01", "veh03", "veh05"}
    assert (
        assert_active_as_predicted(
            run,
            "story0",
            lambda v, t: t >= 190 or (t >= 15 and v in listed and in_canvas_polygon(v, t)),
            ambiguous=on_edge,
        )
        > 100
    )
    assert assert_active_as_predicted(run, "story1", lambda v, t: 50 <= t <= 60) > 100
    assert assert_active_as_predicted(run, "story2", lambda v, t: 200 <= t <= 210 and v in ("veh00", "veh02")) > 10
    assert (
        assert_active_as_predicted(
            run,
            "story3",
            lambda v, t: 20 <= t <= 30 and fcd.speed[v][t] > 4.0,
            ambiguous=lambda v, t: abs(fcd.speed[v][t] - 4.0) < 1e-4,
        )
        > 5
    )
    # story2 (0.1 m/s) overrides story0 (2.44 m/s) for veh00 and veh02 from 200 to 210 s.
    for v in ("veh00", "veh02"):
        assert max(fcd.speeds(v, 205, 211).values()) <= 0.1 + 0.05, v
    # Everybody is capped at 2.44 m/s from 190 s (allow 5 s for braking) and during 50 .. 60 s.
    for t in fcd.times:
        if t >= 195 or 55 <= t <= 61:
            assert all(fcd.speed[v][t] <= 2.44 + 0.05 for v in fcd.running[t]), t
