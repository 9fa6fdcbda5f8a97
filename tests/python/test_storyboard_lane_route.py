"""LaneEffect and RouteEffect end to end, checked against SUMO's own FCD and tripinfo output."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from sbsim.scenarios.grid import make_grid
from sbsim_helpers import StoryRun, run_story

LEFT = ["veh5", "veh6", "veh8", "veh9", "veh10", "veh11"]
RIGHT = ["veh12", "veh13", "veh14"]
CLAMPED = ["veh15", "veh16"]
#: A lane change needs a free gap: the held lane is checked from this long after the activation.
SETTLE = 3.0

STORY = f"""
    import storyboard as sb
    def createStories(board):
        window = sb.TimeCondition(40, 150)
        board.registerStory(sb.Story(sb.AndCondition(window, sb.CarSetCondition({LEFT!r})), [EFFECT(1)], "left"))
        board.registerStory(sb.Story(sb.AndCondition(window, sb.CarSetCondition({RIGHT!r})), [EFFECT(0)], "right"))
        board.registerStory(sb.Story(sb.AndCondition(window, sb.CarSetCondition({CLAMPED!r})), [EFFECT(7)], "clamped"))
        # Until it reaches the target: then it is routed back to its own destination.
        away = sb.NotCondition(sb.RoadCondition("C2B2"))
        board.registerStory(sb.Story(sb.AndCondition(sb.CarSetCondition("veh0"), away), [ROUTE("C2B2")], "detour",
                                     max_activations=1))
        board.registerStory(sb.Story(sb.CarSetCondition("veh1"), [ROUTE(via=["C1C0"])], "via"))
        board.registerStory(sb.Story(sb.CarSetCondition("veh2"), [ROUTE(":A0_0")], "unknown"))
"""


@pytest.fixture(scope="module")
def two_lanes(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """3 x 3 grid with two lanes per direction, one random trip every 4 s (veh0..veh74)."""
    return make_grid(tmp_path_factory.mktemp("lanes"), grid=3, lanes=2, end=300.0, seed=5, period=4.0)


def _run(cfg: Path, directory: Path, effects: bool) -> StoryRun:
    source = STORY.replace("EFFECT", "sb.LaneEffect" if effects else "(lambda k: sb.SignalEffect('k'))")
    source = source.replace("ROUTE", "sb.RouteEffect" if effects else "(lambda *a, **k: sb.SignalEffect('r'))")
    tripinfo = directory / "tripinfo.xml"
    return run_story(cfg, source, directory, fcd=True, sumo_options=(f"--tripinfo-output {tripinfo}",))


@pytest.fixture(scope="module")
def with_effects(two_lanes: Path, tmp_path_factory: pytest.TempPathFactory) -> StoryRun:
    return _run(two_lanes, tmp_path_factory.mktemp("effects"), effects=True)


@pytest.fixture(scope="module")
def without_effects(two_lanes: Path, tmp_path_factory: pytest.TempPathFactory) -> StoryRun:
    """The same stories with signals instead: how the vehicles drive on their own."""
    return _run(two_lanes, tmp_path_factory.mktemp("plain"), effects=False)


def _windows(run: StoryRun, story: str) -> dict[str, tuple[float, float]]:
    """Each vehicle's active time in `story`: activation to deactivation (or its leaving)."""
    starts = {e["vehicle"]: e["t"] for e in run.of(type="activate", story=story)}
    ends = {e["vehicle"]: e["t"] for e in run.of(type="deactivate", story=story)}
    return {v: (t, ends.get(v, float("inf"))) for v, t in starts.items()}


def _lanes(run: StoryRun, vehicle: str, t0: float, t1: float) -> dict[float, int]:
    """Lane index at each sbsim time in [t0, t1) on normal roads (junctions' internal lanes left out)."""
    assert run.fcd is not None
    return {
        t: int(lane.rsplit("_", 1)[1])
        for t, lane in run.fcd.lane[vehicle].items()
        if t0 <= t < t1 and not lane.startswith(":")
    }


def _edges(run: StoryRun, vehicle: str) -> list[str]:
    """The roads `vehicle` drove on, in order, without junctions."""
    assert run.fcd is not None
    edges: list[str] = []
    for _, lane in sorted(run.fcd.lane[vehicle].items()):
        edge = lane.rsplit("_", 1)[0]
        if not lane.startswith(":") and (not edges or edges[-1] != edge):
            edges.append(edge)
    return edges


def _own_route(cfg: Path, vehicle: str) -> list[str]:
    root = ET.parse(cfg.parent / "routes.rou.xml").getroot()
    for v in root.iter("vehicle"):
        if v.attrib["id"] == vehicle:
            route = v.find("route")
            assert route is not None
            return route.attrib["edges"].split()
    raise AssertionError(f"no vehicle {vehicle}")


def _arrival_edge(run: StoryRun, vehicle: str) -> str:
    root = ET.parse(run.story.parent / "tripinfo.xml").getroot()
    for trip in root.iter("tripinfo"):
        if trip.attrib["id"] == vehicle:
            return trip.attrib["arrivalLane"].rsplit("_", 1)[0]
    raise AssertionError(f"{vehicle} did not arrive")


@pytest.mark.parametrize(("story", "lane"), [("left", 1), ("right", 0), ("clamped", 1)])
def test_lane_effect_keeps_the_vehicles_on_their_lane_while_active(
    with_effects: StoryRun, without_effects: StoryRun, story: str, lane: int
) -> None:
    windows = _windows(with_effects, story)
    assert len(windows) >= 2, windows
    on_own_elsewhere = 0
    for vehicle, (t0, t1) in windows.items():
        held = _lanes(with_effects, vehicle, t0 + SETTLE, t1)
        assert len(held) > 5, (vehicle, held)
        assert set(held.values()) == {lane}, f"{vehicle} left lane {lane} while held: {held}"
        on_own_elsewhere += sum(k != lane for k in _lanes(without_effects, vehicle, t0 + SETTLE, t1).values())
    # Left alone, the same vehicles use the other lane in that time: the effect made the difference.
    assert on_own_elsewhere > 0


def test_after_the_lane_effect_the_vehicles_change_lanes_freely(with_effects: StoryRun) -> None:
    changed = []
    for story, lane in (("left", 1), ("right", 0)):
        for vehicle, (_, t1) in _windows(with_effects, story).items():
            if any(k != lane for k in _lanes(with_effects, vehicle, t1 + 1, float("inf")).values()):
                changed.append(vehicle)
    assert changed, "no vehicle left its lane after the stories ended"


def test_route_effect_to_a_target_then_back_to_the_own_destination(
    with_effects: StoryRun, without_effects: StoryRun, two_lanes: Path
) -> None:
    own = _own_route(two_lanes, "veh0")
    assert "C2B2" not in own
    assert "C2B2" not in _edges(without_effects, "veh0")
    assert with_effects.activated("detour") == ["veh0"]
    assert with_effects.of(type="deactivate", story="detour", reason="condition")
    driven = _edges(with_effects, "veh0")
    assert "C2B2" in driven, driven
    assert driven[-1] == own[-1]
    assert _arrival_edge(with_effects, "veh0") == own[-1]


def test_route_effect_via_edges_then_the_own_destination(
    with_effects: StoryRun, without_effects: StoryRun, two_lanes: Path
) -> None:
    own = _own_route(two_lanes, "veh1")
    assert "C1C0" not in _edges(without_effects, "veh1")
    driven = _edges(with_effects, "veh1")
    assert "C1C0" in driven, driven
    assert _arrival_edge(with_effects, "veh1") == own[-1]


def test_a_route_sumo_cannot_find_is_a_counted_warning(with_effects: StoryRun, two_lanes: Path) -> None:
    assert with_effects.activated("unknown") == ["veh2"]
    # An internal edge exists (the run accepts it) but no route ends there.
    expected = (
        "vehicle 'veh2' keeps its route: ChangeTarget failed for vehicle 'veh2', destination edge ':A0_0' unreachable"
    )
    assert expected in with_effects.result.stderr
    assert "sumo warnings:" in with_effects.result.stdout
    assert _arrival_edge(with_effects, "veh2") == _own_route(two_lanes, "veh2")[-1]


@pytest.mark.parametrize(
    ("effect", "message"),
    [
        ("sb.LaneEffect(-1)", "ValueError: LaneEffect needs a lane index >= 0, got -1"),
        ("sb.LaneEffect(1.5)", "TypeError: LaneEffect needs a whole lane index, got 1.5"),
        ("sb.RouteEffect()", "ValueError: RouteEffect needs either target_edge or via=[edges], not both or neither"),
        ("sb.RouteEffect('a', via=['b'])", "ValueError: RouteEffect needs either target_edge or via=[edges]"),
        ("sb.RouteEffect(via='ab')", "TypeError: RouteEffect via must be a list of edge ids, got 'ab'"),
        ("sb.RouteEffect(via=[])", "ValueError: RouteEffect via needs at least one edge"),
        ("sb.RouteEffect('')", "ValueError: RouteEffect edges must not be empty strings"),
        # An id the network does not have: refused when the story is registered, not when it acts.
        ("sb.RouteEffect('nowhere')", "RouteEffect names edges the network does not have: nowhere"),
        ("sb.RouteEffect(via=['B1C1', 'nowhere'])", "RouteEffect names edges the network does not have: nowhere"),
    ],
)
def test_bad_arguments_are_one_line_errors(two_lanes: Path, tmp_path: Path, effect: str, message: str) -> None:
    source = f"""
        import storyboard as sb
        def createStories(board):
            board.registerStory(sb.Story(sb.TimeCondition(1, 2), [{effect}]))
    """
    run = run_story(two_lanes, source, tmp_path, end=2, check=False)
    assert run.returncode == 2
    assert message in run.result.stderr
