"""sbsim --scenario: event actions and storyboard features of issue 31 beyond the first import —
TeleportAction and RoutingAction (AssignRoute, AcquirePosition) in events, a ManeuverGroup's
maximumExecutionCount and selectTriggeringEntities, a lane change by rate, a SpeedAction's
followingMode, relative and continuous
lane offsets, an actor that leaves mid-transition, and the conditions SUMO cannot say (Offroad,
EndOfRoad). Scenarios in tests/openscenario/, each with its expected outcome worked out in its
comment; the straight road and the helpers are test_openscenario.py's, the grid is this file's."""

from __future__ import annotations

from pathlib import Path

import pytest
from sbsim.runner import run
from sbsim_helpers import FcdTrace, assert_bad_input, netgenerate_grid
from test_openscenario import ends, road, run_xosc, scenario, starts

__all__ = ["road"]  # the fixture, shared with test_openscenario.py


@pytest.fixture(scope="module")
def grid(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A 3 x 3 grid of one-lane 200 m roads (A0..C2) without U-turns, and a sumocfg (0.1 s, 100 s)."""
    out = tmp_path_factory.mktemp("xosc-grid")
    options = ("--grid.number=3", "--grid.length=200", "--default.lanenumber=1", "--default.speed=13.89")
    netgenerate_grid(out, "grid", *options, end=100)
    return out


def lane_start_x(net: Path, lane: str) -> float:
    import sumolib

    return float(sumolib.net.readNet(str(net)).getLane(lane).getShape()[0][0])


def edges_driven(fcd: FcdTrace, vehicle: str) -> list[str]:
    """The edges the vehicle was on, in order (junctions' internal lanes left out)."""
    out: list[str] = []
    for t in sorted(fcd.lane[vehicle]):
        edge = fcd.lane[vehicle][t].rsplit("_", 1)[0]
        if not edge.startswith(":") and (not out or out[-1] != edge):
            out.append(edge)
    return out


def signals(events: list[dict], cause: str) -> list[float]:
    return [e["t"] for e in events if e["type"] == "signal" and e["cause"] == cause]


def test_a_teleport_puts_the_entity_at_the_position_at_the_step(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(scenario(tmp_path, "teleport.xosc"), sumocfg=road / "line.sumocfg")
    assert starts(events, "S/A/Jump") == [2.1] and ends(events, "S/A/Jump") == [2.2], "instantaneous"
    # Put at B0C0_1 s = 100 at 2.1 s; in the step to 2.2 s it drives speed(2.2) x 0.1 s (SUMO's Euler update).
    x0 = lane_start_x(road / "line.net.xml", "B0C0_1")
    assert fcd.lane["Ego"][2.2] == "B0C0_1"
    assert fcd.pos["Ego"][2.2][0] - fcd.speed["Ego"][2.2] * 0.1 == pytest.approx(x0 + 100, abs=0.01)
    assert fcd.pos["Ego"][2.0][0] < x0, "it was still on A0B0 before"
    # 30 m behind Lead on Lead's lane, as Lead was when Back started (4.1 s).
    assert starts(events, "S/A/Back") == [4.1]
    assert fcd.lane["Ego"][4.2] == "A0B0_0" == fcd.lane["Lead"][4.1]
    assert fcd.pos["Ego"][4.2][0] - fcd.speed["Ego"][4.2] * 0.1 == pytest.approx(fcd.pos["Lead"][4.1][0] - 30, abs=0.01)


def test_routing_actions_make_the_entities_drive_there(grid: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(scenario(tmp_path, "routing.xosc"), sumocfg=grid / "grid.sumocfg")
    assert starts(events, "S/A/Go") == [1.1] and ends(events, "S/A/Go") == [1.2], "routed at once"
    assert edges_driven(fcd, "Ego")[:3] == ["A0B0", "B0B1", "B1C1"], "AcquirePosition: left at B0, then east"
    assert edges_driven(fcd, "Car")[:3] == ["A0B0", "B0B1", "B1B2"], "AssignRoute: through both waypoints"
    (here,) = signals(events, "here")
    (there,) = signals(events, "there")
    # At most 10 m/s over 190 + 200 + 100 m (Ego) and 140 + 200 + 50 m (Car), junctions aside.
    assert here >= 49 and there >= 39
    assert fcd.lane["Ego"][here] == "B1C1_0" and fcd.lane["Car"][there] == "B1B2_0"
    # A teleport off the route: routed there first, moved, then on along B1C1.
    x0 = lane_start_x(grid / "grid.net.xml", "B1C1_0")
    assert fcd.lane["Hop"][1.1] == "A0B0_0" and fcd.lane["Hop"][1.2] == "B1C1_0"
    assert fcd.pos["Hop"][1.2][0] - fcd.speed["Hop"][1.2] * 0.1 == pytest.approx(x0 + 50, abs=0.01)
    assert edges_driven(fcd, "Hop")[:2] == ["A0B0", "B1C1"]


def test_an_init_acquire_position_routes_the_entity_there(grid: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(scenario(tmp_path, "acquire-init.xosc"), sumocfg=grid / "grid.sumocfg")
    assert edges_driven(fcd, "Far")[:3] == ["A0B0", "B0B1", "B1C1"]
    (here,) = signals(events, "here")
    assert here >= 49 and fcd.lane["Far"][here] == "B1C1_0"


def test_a_maneuver_group_with_maximum_execution_count_two_runs_twice(road: Path, tmp_path: Path) -> None:
    events, _ = run_xosc(scenario(tmp_path, "group-twice.xosc"), sumocfg=road / "line.sumocfg")
    assert signals(events, "tick") == [1.1, 1.3]
    assert starts(events, "S/A/Tick") == [1.1, 1.3] and ends(events, "S/A/Tick") == [1.2, 1.4]


def test_select_triggering_entities_acts_on_the_entity_that_fired(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(scenario(tmp_path, "select-triggering.xosc"), sumocfg=road / "line.sumocfg")
    slowed = [(e["t"], e["vehicle"]) for e in events if e["type"] == "activate" and e["story"] == "S/A/Slow"]
    assert [v for _, v in slowed] == ["B"], "B's speed > 15 m/s started the act; A's never was"
    marks = [e["vehicle"] for e in events if e["type"] == "signal" and e["cause"] == "slow"]
    assert marks == ["B"]
    (t,) = [t for t, _ in slowed]
    assert fcd.speed["B"][round(t + 2.0, 1)] == pytest.approx(5.0), "15 m/s down at 8 m/s^2 within 1.9 s"
    assert fcd.speed["A"][round(t + 2.0, 1)] == pytest.approx(10.0)
    xosc = scenario(tmp_path / "check", "select-triggering.xosc")
    check = run(road / "line.sumocfg", extra=["check", "--scenario", str(xosc)], timeout=120)
    assert check.returncode == 0, check.stderr
    assert "ElementCondition(Event 'Slow', actors: the entities that triggered its act)" in check.stdout
    assert "TriggeringEntitiesCondition(any of A, B)" in check.stdout


def test_a_lane_change_by_rate_takes_distance_over_rate(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(
        scenario(tmp_path, "lane-change-rate.xosc"), sumocfg=road / "line.sumocfg", sumo="--lateral-resolution 0.8"
    )
    assert starts(events, "S/A/Change") == [2.1]
    y = {t: p[1] for t, p in fcd.pos["Ego"].items()}
    y0, y1 = y[2.0], y[max(y)]
    assert abs(y1 - y0) == pytest.approx(3.2, abs=0.01), "one lane width across"
    moving = sorted(t for t in y if abs(y[t] - y0) > 1e-3)
    done = min(t for t in moving if abs(y[t] - y1) < 1e-3)
    assert done - moving[0] == pytest.approx(2.0 - 0.1, abs=0.1 + 1e-9), "3.2 m at 1.6 m/s: 2 s, 0.16 m a step"
    assert abs(y[moving[0]] - y0) == pytest.approx(0.16, abs=0.01)
    (end,) = ends(events, "S/A/Change")
    assert end == pytest.approx(2.1 + 2.1, abs=0.1 + 1e-9)


def test_following_mode_follow_keeps_the_entitys_own_dynamics(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(scenario(tmp_path, "following-mode.xosc"), sumocfg=road / "line.sumocfg")
    assert starts(events, "S/A/Exact") == [2.1] == starts(events, "S/A/Follow")
    exact, follow = fcd.speed["Exact"], fcd.speed["Follow"]
    assert exact[3.1] == pytest.approx(30.0), "position: the shape exactly, 20 m/s^2"
    assert follow[3.1] == pytest.approx(14.0), "follow: at most its maxAcceleration, 4 m/s^2"
    assert min(t for t, v in follow.items() if v >= 30 - 1e-6) == pytest.approx(7.1), "30 m/s after 20 / 4 = 5 s"
    assert ends(events, "S/A/Exact") == [3.1] == ends(events, "S/A/Follow"), "the shape's 1 s has run"


def test_relative_and_continuous_lane_offsets(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(
        scenario(tmp_path, "lane-offset-relative.xosc"),
        sumocfg=road / "line.sumocfg",
        sumo="--lateral-resolution 0.8",
    )
    lead = {t: p[1] for t, p in fcd.pos["Lead"].items()}
    ego = {t: p[1] for t, p in fcd.pos["Ego"].items()}
    assert lead[3.0] - lead[1.0] == pytest.approx(0.5, abs=0.01), "LeadOff: 0.5 m at once"
    # EgoOff: Lead's 0.5 m + 0.3 m (after it ends SUMO centres Ego again).
    reached = min(t for t in ego if t > 3 and abs(ego[t] - ego[3.0] - 0.8) < 1e-3)
    assert reached == pytest.approx(3.1 + 2.19, abs=0.2), "cubic within 1 m/s^2: sqrt(6 x 0.8) s"
    assert starts(events, "S/A/EgoOff") == [3.1]
    (end,) = ends(events, "S/A/EgoOff")
    assert reached - 1e-9 <= end <= reached + 0.1 + 1e-9, "it ends once the step that reaches the offset is commanded"
    assert starts(events, "S/A/LeadOff") == [1.1]
    assert [t for t in ends(events, "S/A/LeadOff") if t < 8.0] == [], "continuous: held until the run stops"
    assert lead[7.9] - lead[1.0] == pytest.approx(0.5, abs=0.01)


def test_an_event_whose_actor_leaves_mid_transition_ends(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(scenario(tmp_path, "leave.xosc"), sumocfg=road / "line.sumocfg")
    assert starts(events, "S/A/Speed") == [1.1]
    left = [(e["t"], e["reason"]) for e in events if e["type"] == "deactivate" and e["story"] == "S/A/Speed"]
    assert left == [(3.2, "vehicle_left")]
    assert max(fcd.speed["Ego"]) == 3.1, "deleted in the step of 3.1 s"
    assert signals(events, "after") == [3.2], "Speed's endTransition at 3.2 s, not at the run's end"


@pytest.mark.parametrize(
    ("condition", "needle"),
    [
        ('<OffroadCondition duration="1"/>', "never off the road"),
        ('<EndOfRoadCondition duration="1"/>', "arrives and leaves the simulation"),
    ],
)
def test_offroad_and_end_of_road_are_errors_saying_why(road: Path, tmp_path: Path, condition: str, needle: str) -> None:
    xosc = scenario(tmp_path, "leave.xosc")
    text = xosc.read_text()
    start = text.index('<ByValueCondition><SimulationTimeCondition value="3"')
    stop = text.index("</ByValueCondition>", start) + len("</ByValueCondition>")
    entity = (
        '<ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/>'
        f"</TriggeringEntities><EntityCondition>{condition}</EntityCondition></ByEntityCondition>"
    )
    xosc.write_text(text[:start] + entity + text[stop:])
    result = run(road / "line.sumocfg", extra=["--scenario", str(xosc)], timeout=120)
    assert_bad_input(result, "1 unsupported OpenSCENARIO element", needle)
