"""`sbsim check`: stories printed as trees, likely mistakes warned about, nothing run."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from sbsim.runner import RunResult, run
from sbsim_helpers import STORIES, assert_no_crash, write_story


def check(cfg: Path, story: Path, *flags: str) -> RunResult:
    result = run(cfg, story=story, extra=["check", *flags], timeout=120)
    assert_no_crash(result)
    return result


@pytest.mark.parametrize("folder", sorted(p.name for p in STORIES.iterdir() if (p / "story.py").exists()))
def test_every_bundled_story_checks_clean(folder: str) -> None:
    (cfg,) = (STORIES / folder).glob("*.sumocfg")
    result = check(cfg, STORIES / folder / "story.py", "--strict")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "story '" in result.stdout and result.stdout.rstrip().endswith("0 warnings")


TREE = """
    import storyboard
    from storyboard import AndCondition, PolygonCondition, SpeedEffect, Story, TimeCondition

    def createStories(board):
        area = PolygonCondition([(100, 100), (300, 100), (300, 300)])
        board.registerStory(Story(AndCondition(area, TimeCondition(10, 50)), [SpeedEffect(5)], name="slow"))
"""


def test_the_tree_is_printed_and_nothing_runs(offset_cfg: Path, tmp_path: Path) -> None:
    events = tmp_path / "ev.jsonl"
    story = write_story(tmp_path, TREE)
    result = run(offset_cfg, story=story, events=events, extra=["check"], timeout=120)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    at = lines.index("story 'slow'")
    assert lines[at + 1 : at + 5] == [
        "  AndCondition",
        "    PolygonCondition(3 points, SUMO frame: (100, 100) (300, 100) (300, 300))",
        "    TimeCondition(10 s, 50 s)",
        "  → SpeedEffect(5 m/s)",
    ]
    assert not events.exists() and "steps:" not in result.stdout


# The offset scenario's boundary is x -100..700, y -50..650; Coord(x, y) is SUMO (x - 100, 650 - y).
WRONG_FRAME = {
    # Canvas values written as tuples: x 720..780 is beyond the net, but as Coord it fits.
    "tuples": ("[(720, 100), (780, 100), (780, 200), (720, 200)]", "Artery's canvas frame", "Coord(x, y)"),
    # SUMO values written as Coord: x -90..-60 becomes -190..-160, but as tuples it fits.
    "coords": ("[Coord(-90, 100), Coord(-60, 100), Coord(-60, 200), Coord(-90, 200)]", "SUMO frame", "(x, y) tuples"),
}


@pytest.mark.parametrize("case", sorted(WRONG_FRAME))
def test_a_polygon_in_the_wrong_frame_is_found_and_the_right_frame_named(
    offset_cfg: Path, tmp_path: Path, case: str
) -> None:
    points, frame, advice = WRONG_FRAME[case]
    story = write_story(
        tmp_path,
        f"""
        from storyboard import Coord, PolygonCondition, SpeedEffect, Story

        def createStories(board):
            board.registerStory(Story(PolygonCondition({points}), [SpeedEffect(5)], name="district"))
        """,
    )
    assert check(offset_cfg, story).returncode == 0
    result = check(offset_cfg, story, "--strict")
    assert result.returncode == 1, result.stderr
    (warning,) = [line for line in result.stderr.splitlines() if "warning" in line]
    assert "story 'district'" in warning and "outside the network boundary" in warning
    assert frame in warning and advice in warning, warning


def test_the_other_warnings_and_json(trips_cfg: Path, tmp_path: Path) -> None:
    story = write_story(
        tmp_path,
        """
        from storyboard import (AllCondition, CarSetCondition, LimitCondition, SpeedEffect, StopEffect, Story,
                                TimeCondition)

        def createStories(board):
            board.registerStory(Story(CarSetCondition({"veh3", "nobody"}), [SpeedEffect(5)], name="cars"))
            board.registerStory(Story(TimeCondition(5000, 6000), [SpeedEffect(5)], name="late"))
            board.registerStory(Story(LimitCondition(0), [SpeedEffect(5)], name="none"))
            board.registerStory(Story(AllCondition(TimeCondition(10, 20), TimeCondition(30, 40)), [], name="never"))
            board.registerStory(Story(TimeCondition(10), [SpeedEffect(5), StopEffect()], name="fight"))
        """,
    )
    result = check(trips_cfg, story, "--json", "--strict")
    assert result.returncode == 1, result.stderr
    document = json.loads(result.stdout)
    assert [s["name"] for s in document["stories"]] == ["cars", "late", "none", "never", "fight"]
    warnings = {w["story"]: w["message"] for w in document["warnings"]}
    assert set(warnings) == {"cars", "late", "none", "never", "fight"}, warnings
    assert "nobody" in warnings["cars"] and "veh3" not in warnings["cars"]
    assert "outside the run" in warnings["late"]
    assert "LimitCondition(0)" in warnings["none"]
    assert "never hold" in warnings["never"]
    assert "same domain (speed)" in warnings["fight"]


def test_json_gives_each_story_its_areas_in_sumo_frame(offset_cfg: Path, tmp_path: Path) -> None:
    story = write_story(
        tmp_path,
        """
        from storyboard import (AndCondition, Coord, DistanceCondition, OrCondition, PolygonCondition, SpeedEffect,
                                Story, TimeCondition)

        def createStories(board):
            canvas = PolygonCondition([Coord(0, 0), Coord(200, 0), Coord(200, 100)])
            sumo = PolygonCondition([(10, 20), (30, 20), (30, 40)])
            near = DistanceCondition(Coord(100, 150), 25)
            shared = AndCondition(canvas, TimeCondition(10))
            board.registerStory(Story(OrCondition(shared, AndCondition(sumo, shared)), [SpeedEffect(5)], name="a"))
            board.registerStory(Story(AndCondition(near, DistanceCondition("veh0", 10)), [], name="b"))
            board.registerStory(Story(TimeCondition(10), [], name="c"))
        """,
    )
    result = check(offset_cfg, story, "--json")
    assert result.returncode == 0, result.stderr
    areas = {s["name"]: s["areas"] for s in json.loads(result.stdout)["stories"]}
    # Coord(x, y) is SUMO (x - 100, 650 - y) here; the shared polygon once; a vehicle distance has no area.
    assert areas == {
        "a": [
            {"condition": "PolygonCondition", "points": [[-100, 650], [100, 650], [100, 550]]},
            {"condition": "PolygonCondition", "points": [[10, 20], [30, 20], [30, 40]]},
        ],
        "b": [{"condition": "DistanceCondition", "points": [[0, 500]], "radius": 25}],
        "c": [],
    }


UNKNOWN_IDS = {
    "edge": ('Story(RoadCondition({"B1C1", "nowhere"}), [SpeedEffect(5)], name="s")', "RoadCondition", "nowhere"),
    "traffic light": (
        'WorldStory(TimeCondition(10), [TrafficLightEffect("Z9", "r")], name="s")',
        "TrafficLightEffect",
        "Z9",
    ),
    "type": ('Story(TimeCondition(10), [TypeEffect("bus9")], name="s")', "TypeEffect", "bus9"),
}
ID_IMPORTS = (
    "from storyboard import RoadCondition, SpeedEffect, Story, TimeCondition, TrafficLightEffect, TypeEffect, "
    "WorldStory"
)


@pytest.mark.parametrize("case", sorted(UNKNOWN_IDS))
def test_ids_the_network_lacks_are_warned_naming_them(trips_cfg: Path, tmp_path: Path, case: str) -> None:
    story_text, who, unknown = UNKNOWN_IDS[case]
    story = tmp_path / "story.py"
    story.write_text(f"{ID_IMPORTS}\n\ndef createStories(board):\n    board.registerStory({story_text})\n")
    assert check(trips_cfg, story).returncode == 0
    result = check(trips_cfg, story, "--strict")
    assert result.returncode == 1, result.stdout + result.stderr
    (warning,) = [line for line in result.stderr.splitlines() if "warning" in line]
    assert "story 's'" in warning and who in warning and unknown in warning, warning
    assert "B1C1" not in warning, warning


def test_ids_the_network_has_pass_and_are_printed(trips_cfg: Path, tmp_path: Path) -> None:
    # An internal edge is a road too; "truck" is a type of the route file; B1 a traffic light.
    story = write_story(
        tmp_path,
        """
        from storyboard import (LaneCondition, RoadCondition, RouteEffect, Story, TimeCondition, TrafficLightEffect,
                                TypeEffect, WorldStory)

        def createStories(board):
            board.registerStory(Story(RoadCondition({"B1C1", ":B1_0"}), [TypeEffect("truck")], name="road"))
            board.registerStory(Story(LaneCondition({"B1C1_0"}), [RouteEffect(target_edge="C1C2")], name="lane"))
            board.registerStory(WorldStory(TimeCondition(10), [TrafficLightEffect("B1", "r")], name="light"))
        """,
    )
    result = check(trips_cfg, story, "--strict")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "  RoadCondition(:B1_0, B1C1)" in result.stdout.splitlines()
    assert "  LaneCondition(B1C1_0)" in result.stdout.splitlines()
    assert "  → RouteEffect(to C1C2)" in result.stdout.splitlines()


def test_python_conditions_and_effects_are_printed_by_their_class_name(trips_cfg: Path, tmp_path: Path) -> None:
    story = write_story(
        tmp_path,
        """
        import storyboard
        from storyboard import AndCondition, Story, TimeCondition

        class IsTruck(storyboard.Condition):
            def test(self, vehicle):
                return vehicle.type == "truck"

        class Honk(storyboard.Effect):
            def apply(self, vehicle):
                pass
            def remove(self, vehicle):
                pass

        def createStories(board):
            board.registerStory(Story(AndCondition(IsTruck(), TimeCondition(10)), [Honk()], name="py"))
        """,
    )
    result = check(trips_cfg, story, "--strict")
    assert result.returncode == 0, result.stdout + result.stderr
    lines = result.stdout.splitlines()
    at = lines.index("story 'py'")
    assert lines[at + 1 : at + 5] == ["  AndCondition", "    IsTruck", "    TimeCondition(10 s, end)", "  → Honk"]


BROKEN = {
    "syntax": ("x = = 1", "x = = 1", "SyntaxError"),
    "name": ("    board.registerStory(Story(Nope(), []))", "Nope()", "NameError"),
    "raise": ("    raise RuntimeError('no stories today')", "raise RuntimeError", "no stories today"),
    "few points": ("    PolygonCondition([(0, 0), (1, 1)])", "PolygonCondition(", "3 or more points"),
    "bad type": ("    Story(TimeCondition('soon'), [])", "TimeCondition('soon')", "TimeCondition"),
    "negative limit": ("    LimitCondition(-1)", "LimitCondition(-1)", "LimitCondition"),
    "nan speed": ("    SpeedEffect(float('nan'))", "SpeedEffect(float", "SpeedEffect"),
    "none effect": ("    board.registerStory(Story(TimeCondition(1), [None]))", "[None]", "None"),
    "import": ("    import no_such_module_here", "import no_such", "ModuleNotFoundError"),
    "zero division": ("    TimeCondition(1 / 0)", "1 / 0", "ZeroDivisionError"),
}


@pytest.mark.parametrize("case", sorted(BROKEN))
def test_broken_scripts_are_errors_with_file_and_line(trips_cfg: Path, tmp_path: Path, case: str) -> None:
    body, marker, needle = BROKEN[case]
    source = (
        "from storyboard import LimitCondition, PolygonCondition, SpeedEffect, Story, TimeCondition\n\n"
        "def createStories(board):\n"
        "    pass\n" + body + "\n"
    )
    story = tmp_path / "story.py"
    story.write_text(source, encoding="utf-8")
    result = check(trips_cfg, story)
    assert result.returncode == 2, result.stdout + result.stderr
    line = next(n for n, text in enumerate(source.splitlines(), start=1) if marker in text)
    assert f"{story}:{line}" in result.stderr, result.stderr
    assert needle in result.stderr, result.stderr
