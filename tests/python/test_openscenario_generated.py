"""OpenSCENARIO files written by the `scenariogeneration` package (PyPI), not by hand: its OpenDRIVE
road and an overtaking in the shape of ASAM's example, generated here, validated against the ASAM
schema of their revision and run by sbsim. The expected times are worked out below from the
generated values; SUMO steps 0.1 s and an entity appears at 0.2 s (sbsim's clock).

The overtaking: a straight 1 km road, two lanes of 3.5 m (OpenDRIVE -1 next to the centre line, -2
outside). Ego starts at s = 50 m on lane -2 at 35 m/s, Slow at s = 200 m on the same lane at
$SlowSpeed (20 m/s): their centres are 150 m apart and close at 15 m/s.
- Out (rising, distance < 90 m): 150 - 15 (t - 0.2) < 90 first at t = 4.3; a sinusoidal lane change
  of 3 s to lane -1: 3.5 m to the left, half of it at 5.8, done at 7.3.
- Back: 6 s after Out completes (the condition's delay), at 13.3, Ego back to lane -2 in 3 s, done
  at 16.3, now in front of Slow (it passed it at about 10.5 s).
With --param SlowSpeed=15 they close at 20 m/s: 150 - 20 (t - 0.2) < 90 first at t = 3.3.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from test_openscenario import run_xosc

xodr = pytest.importorskip("scenariogeneration.xodr")
xosc = pytest.importorskip("scenariogeneration.xosc")

OUT = "S/Overtake/Out"
BACK = "S/Overtake/Back"
SUMO = "--lateral-resolution 0.8"


def generate(folder: Path) -> Path:
    """The road and the overtaking, as scenariogeneration writes them (OpenSCENARIO 1.2)."""
    odr = xodr.OpenDrive("straight")
    odr.add_road(xodr.create_road(xodr.Line(1000), id=1, left_lanes=0, right_lanes=2, lane_width=3.5))
    odr.adjust_roads_and_lanes()
    odr.write_xml(str(folder / "straight.xodr"))

    box = xosc.BoundingBox(2.0, 5.0, 1.8, 1.4, 0, 0.9)
    front, rear = xosc.Axle(0.5, 0.6, 1.8, 3.1, 0.3), xosc.Axle(0, 0.6, 1.8, 0, 0.3)
    entities = xosc.Entities()
    for name in ("Ego", "Slow"):
        vehicle = xosc.Vehicle(name.lower(), xosc.VehicleCategory.car, box, front, rear, 69, 4, 8)
        entities.add_scenario_object(name, vehicle)
    parameters = xosc.ParameterDeclarations()
    parameters.add_parameter(xosc.Parameter("SlowSpeed", xosc.ParameterType.double, "20"))

    step = xosc.TransitionDynamics(xosc.DynamicsShapes.step, xosc.DynamicsDimension.time, 0)
    init = xosc.Init()
    init.add_init_action("Ego", xosc.TeleportAction(xosc.LanePosition(50, 0, -2, 1)))
    init.add_init_action("Ego", xosc.AbsoluteSpeedAction(35, step))
    init.add_init_action("Slow", xosc.TeleportAction(xosc.LanePosition(200, 0, -2, 1)))
    init.add_init_action("Slow", xosc.AbsoluteSpeedAction("$SlowSpeed", step))

    sine = xosc.TransitionDynamics(xosc.DynamicsShapes.sinusoidal, xosc.DynamicsDimension.time, 3)
    euclidean = xosc.RelativeDistanceType.euclidianDistance
    out = xosc.Event("Out", xosc.Priority.override)
    out.add_action("out", xosc.AbsoluteLaneChangeAction(-1, sine))
    close = xosc.RelativeDistanceCondition(90, xosc.Rule.lessThan, euclidean, "Slow", freespace=False)
    out.add_trigger(xosc.EntityTrigger("close", 0, xosc.ConditionEdge.rising, close, "Ego"))
    back = xosc.Event("Back", xosc.Priority.override)
    back.add_action("back", xosc.AbsoluteLaneChangeAction(-2, sine))
    done = xosc.StoryboardElementStateCondition(
        xosc.StoryboardElementType.event, "Out", xosc.StoryboardElementState.completeState
    )
    back.add_trigger(xosc.ValueTrigger("out_done", 6, xosc.ConditionEdge.none, done))
    maneuver = xosc.Maneuver("M")
    maneuver.add_event(out)
    maneuver.add_event(back)
    group = xosc.ManeuverGroup("G")
    group.add_actor("Ego")
    group.add_maneuver(maneuver)
    start = xosc.ValueTrigger("go", 0, xosc.ConditionEdge.none, xosc.SimulationTimeCondition(0, xosc.Rule.greaterThan))
    act = xosc.Act("Overtake", start)
    act.add_maneuver_group(group)
    story = xosc.Story("S")
    story.add_act(act)
    end = xosc.ValueTrigger(
        "end", 0, xosc.ConditionEdge.none, xosc.SimulationTimeCondition(20, xosc.Rule.greaterThan), "stop"
    )
    board = xosc.StoryBoard(init, end)
    board.add_story(story)
    scenario = xosc.Scenario(
        "overtaking",
        "sbsim",
        parameters,
        entities,
        board,
        xosc.RoadNetwork("straight.xodr"),
        xosc.Catalog(),
        osc_minor_version=2,
    )
    path = folder / "overtaking.xosc"
    scenario.write_xml(str(path))
    return path


def the_start(events: list[dict[str, object]], story: str) -> float:
    (t,) = [e["t"] for e in events if e["type"] == "activate" and e["story"] == story]
    assert isinstance(t, float)
    return t


def test_a_generated_overtaking_on_a_generated_road(tmp_path: Path) -> None:
    xosc_file = generate(tmp_path)
    events, fcd = run_xosc(xosc_file, sumo=SUMO)
    assert "origId" in (tmp_path / ".sbsim" / "straight.net.xml").read_text(), "the generated road, converted"

    out = the_start(events, OUT)
    assert out == pytest.approx(4.3)
    distance = {t: abs(fcd.pos["Slow"][t][0] - fcd.pos["Ego"][t][0]) for t in fcd.pos["Ego"] if t in fcd.pos["Slow"]}
    assert distance[out] < 90 <= distance[round(out - 0.1, 1)], "the first step closer than 90 m"

    # Lane -2 is SUMO's lane 0, lane -1 its lane 1; the sinusoidal move: half at 1.5 s, whole at 3 s.
    y0 = fcd.pos["Ego"][round(out - 0.1, 1)][1]
    assert fcd.lane["Ego"][round(out - 0.1, 1)] == "-1_0"
    assert fcd.pos["Ego"][round(out + 1.5, 1)][1] - y0 == pytest.approx(1.75, abs=0.15)
    assert fcd.pos["Ego"][round(out + 3.0, 1)][1] - y0 == pytest.approx(3.5, abs=0.05)
    assert fcd.lane["Ego"][round(out + 3.0, 1)] == "-1_1"

    back = the_start(events, BACK)
    assert back == pytest.approx(out + 3.0 + 6.0), "6 s after Out completed"
    assert fcd.pos["Ego"][back][0] - fcd.pos["Slow"][back][0] > 5.0, "Ego has passed Slow (5 m long)"
    done = round(back + 3.0, 1)
    assert fcd.lane["Ego"][done] == fcd.lane["Slow"][done] == "-1_0"
    assert fcd.pos["Ego"][done][1] == pytest.approx(y0, abs=0.05)
    assert fcd.pos["Ego"][done][0] > fcd.pos["Slow"][done][0] + 5.0


def test_a_generated_parameter_overridden(tmp_path: Path) -> None:
    events, fcd = run_xosc(generate(tmp_path), "--param", "SlowSpeed=15", sumo=SUMO)
    assert fcd.speed["Slow"][1.0] == pytest.approx(15.0)
    assert the_start(events, OUT) == pytest.approx(3.3)
