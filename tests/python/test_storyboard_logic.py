"""Story logic (Not, All/Any, Hold, Rising, Latch, max_activations) and the conditions read from the snapshot
(distance, standstill, acceleration, road, lane, type), checked step by step against SUMO's FCD output."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from sbsim_helpers import StoryRun, assert_active_as_predicted, run_story

STEP = 1.0
CENTRE = (300.0, 300.0)  # SUMO coordinates inside the 4 x 4 grid (200 m spacing)


def _edges(sumocfg: Path) -> list[str]:
    net = ET.parse(sumocfg.parent / "net.net.xml").getroot()
    return sorted(e.attrib["id"] for e in net.iter("edge") if e.attrib.get("function") != "internal")


@pytest.fixture(scope="module")
def logic_run(trips_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> StoryRun:
    roads = _edges(trips_cfg)[:4]
    story = f"""
        import storyboard as sb
        def createStories(board):
            standing = sb.SpeedConditionLess(0.1)
            board.registerStory(sb.Story(sb.HoldCondition(standing, 5), [], "hold"))
            board.registerStory(sb.Story(sb.StandstillCondition(5), [], "standstill"))
            board.registerStory(sb.Story(sb.RisingCondition(standing), [sb.SignalEffect("stopped")], "rising"))
            board.registerStory(sb.Story(standing, [], "once", max_activations=1))
            board.registerStory(sb.Story(sb.NotCondition(sb.SpeedConditionGreater(0)), [], "not_moving"))
            board.registerStory(sb.Story(sb.all_of(sb.SpeedConditionGreater(2), sb.SpeedConditionLess(8),
                                                   sb.NotCondition(sb.TypeCondition("truck"))), [], "all"))
            board.registerStory(sb.Story(sb.AnyCondition(sb.SpeedConditionGreater(12), sb.TypeCondition("tr.*")),
                                         [], "any"))
            board.registerStory(sb.Story(sb.DistanceCondition({CENTRE!r}, 150), [], "near_point"))
            board.registerStory(sb.Story(sb.once(sb.DistanceCondition({CENTRE!r}, 150)), [], "was_near_point"))
            board.registerStory(sb.Story(sb.DistanceCondition("veh3", 100), [sb.SignalEffect("near")], "near_veh3"))
            board.registerStory(sb.Story(sb.RoadCondition({roads!r}), [], "roads"))
            board.registerStory(sb.Story(sb.LaneCondition({[r + "_0" for r in roads[:2]]!r}), [], "lanes"))
            board.registerStory(sb.Story(sb.AccelerationConditionLess(-1.5), [], "braking"))
            board.registerStory(sb.Story(sb.AccelerationConditionGreater(1.0), [], "speeding_up"))
    """
    return run_story(trips_cfg, story, tmp_path_factory.mktemp("logic"), end=200, fcd=True)


def _standing_for(run: StoryRun, v: str, t: float, seconds: float) -> bool:
    fcd = run.fcd
    assert fcd is not None
    k = 0
    while k * STEP <= seconds + 1e-9:
        s = fcd.speed[v].get(round(t - k * STEP, 3))
        if s is None or s >= 0.1:
            return False
        k += 1
    return True


@pytest.mark.parametrize("story", ["hold", "standstill"])
def test_hold_and_standstill_need_five_seconds_of_standing(logic_run: StoryRun, story: str) -> None:
    n = assert_active_as_predicted(logic_run, story, lambda v, t: _standing_for(logic_run, v, t, 5.0))
    assert n > 20


def test_rising_is_active_for_exactly_one_step(logic_run: StoryRun) -> None:
    fcd = logic_run.fcd
    assert fcd is not None
    n = assert_active_as_predicted(
        logic_run,
        "rising",
        lambda v, t: fcd.speed[v][t] < 0.1 and fcd.speed[v].get(round(t - STEP, 3), 1.0) >= 0.1,
    )
    assert n > 20
    assert len(logic_run.of(type="signal", story="rising")) == n


def test_max_activations_activates_each_vehicle_once(logic_run: StoryRun) -> None:
    activated = logic_run.activated("once")
    assert len(activated) == len(set(activated)) > 20
    # Vehicles stopping more than once exist, so the limit did something.
    assert len(logic_run.activated("rising")) > len(activated)


def test_not_all_and_any(logic_run: StoryRun) -> None:
    fcd = logic_run.fcd
    assert fcd is not None
    assert assert_active_as_predicted(logic_run, "not_moving", lambda v, t: fcd.speed[v][t] <= 0) > 20
    assert (
        assert_active_as_predicted(
            logic_run,
            "all",
            lambda v, t: 2 < fcd.speed[v][t] < 8 and fcd.type[v][t] != "truck",
            ambiguous=lambda v, t: min(abs(fcd.speed[v][t] - 2), abs(fcd.speed[v][t] - 8)) < 1e-4,
        )
        > 20
    )
    assert (
        assert_active_as_predicted(
            logic_run,
            "any",
            lambda v, t: fcd.speed[v][t] > 12 or fcd.type[v][t] == "truck",
            ambiguous=lambda v, t: abs(fcd.speed[v][t] - 12) < 1e-4,
        )
        > 20
    )


def test_distance_to_a_point_and_to_a_vehicle(logic_run: StoryRun) -> None:
    fcd = logic_run.fcd
    assert fcd is not None
    assert (
        assert_active_as_predicted(
            logic_run,
            "near_point",
            lambda v, t: math.dist(fcd.pos[v][t], CENTRE) <= 150,
            ambiguous=lambda v, t: abs(math.dist(fcd.pos[v][t], CENTRE) - 150) < 1e-3,
        )
        > 20
    )

    def near_veh3(v: str, t: float) -> bool:
        return v != "veh3" and "veh3" in fcd.running[t] and math.dist(fcd.pos[v][t], fcd.pos["veh3"][t]) <= 100

    def edge(v: str, t: float) -> bool:
        return "veh3" in fcd.running[t] and abs(math.dist(fcd.pos[v][t], fcd.pos["veh3"][t]) - 100) < 1e-3

    assert assert_active_as_predicted(logic_run, "near_veh3", near_veh3, ambiguous=edge) > 5
    signals = logic_run.of(type="signal", story="near_veh3")
    assert signals and all(s["others"] == ["veh3"] for s in signals)


def test_once_near_stays_true_until_the_vehicle_leaves(logic_run: StoryRun) -> None:
    fcd = logic_run.fcd
    assert fcd is not None

    def distances_so_far(v: str, t: float) -> list[float]:
        return [math.dist(p, CENTRE) for when, p in fcd.pos[v].items() if when <= t]

    latched = assert_active_as_predicted(
        logic_run,
        "was_near_point",
        lambda v, t: min(distances_so_far(v, t)) <= 150,
        ambiguous=lambda v, t: any(abs(d - 150) < 1e-3 for d in distances_so_far(v, t)),
    )
    near = assert_active_as_predicted(
        logic_run,
        "near_point",
        lambda v, t: math.dist(fcd.pos[v][t], CENTRE) <= 150,
        ambiguous=lambda v, t: abs(math.dist(fcd.pos[v][t], CENTRE) - 150) < 1e-3,
    )
    assert latched > near + 20  # vehicles drove off and stayed latched
    # One activation per vehicle: a latch never lets go while the vehicle runs.
    activated = logic_run.activated("was_near_point")
    assert len(activated) == len(set(activated)) > 5


def test_road_and_lane(logic_run: StoryRun, trips_cfg: Path) -> None:
    fcd = logic_run.fcd
    assert fcd is not None
    roads = set(_edges(trips_cfg)[:4])
    lanes = {r + "_0" for r in _edges(trips_cfg)[:2]}
    assert assert_active_as_predicted(logic_run, "roads", lambda v, t: fcd.lane[v][t].rsplit("_", 1)[0] in roads) > 20
    assert assert_active_as_predicted(logic_run, "lanes", lambda v, t: fcd.lane[v][t] in lanes) > 5


@pytest.mark.parametrize(("story", "greater", "threshold"), [("braking", False, -1.5), ("speeding_up", True, 1.0)])
def test_acceleration_from_the_speed_change(logic_run: StoryRun, story: str, greater: bool, threshold: float) -> None:
    fcd = logic_run.fcd
    assert fcd is not None

    def accel(v: str, t: float) -> float | None:
        before = fcd.speed[v].get(round(t - STEP, 3))
        return None if before is None else (fcd.speed[v][t] - before) / STEP

    def predicted(v: str, t: float) -> bool:
        a = accel(v, t)
        assert a is not None
        return a > threshold if greater else a < threshold

    def ambiguous(v: str, t: float) -> bool:
        a = accel(v, t)
        return a is None or abs(a - threshold) < 1e-3  # the first step reads SUMO's own value

    assert assert_active_as_predicted(logic_run, story, predicted, ambiguous=ambiguous) > 20
