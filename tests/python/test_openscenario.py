"""sbsim --scenario: OpenSCENARIO files of tests/openscenario/ run as stories, on a straight
two-lane road netgenerate makes (A0B0, B0C0, C0D0: 3 x 500 m, 33.33 m/s) or on the OpenDRIVE highway
of the corpus; every expected time is worked out in the scenario's comment. SUMO steps 0.1 s; an
entity's speed changes by at most its maxAcceleration / maxDeceleration per second (SUMO's setSpeed)."""

from __future__ import annotations

import json
import os
import re
import shutil
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from sbsim.events import read_events
from sbsim.runner import executable, run
from sbsim_helpers import FcdTrace, assert_bad_input, assert_no_crash, netgenerate_grid, read_fcd

CORPUS = Path(__file__).resolve().parents[1] / "openscenario"


@pytest.fixture(scope="module")
def road(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The straight road and a sumocfg (0.1 s steps, 60 s); veh0 drives it from t = 0 (for --bind)."""
    out = tmp_path_factory.mktemp("xosc-road")
    line = ("--grid.x-number=4", "--grid.y-number=1", "--grid.length=500", "--default.lanenumber=2")
    netgenerate_grid(out, "line", *line, "--default.speed=33.33")
    (out / "veh0.rou.xml").write_text(
        '<routes><vehicle id="veh0" depart="0" departSpeed="10" departPos="20">'
        '<route edges="A0B0 B0C0 C0D0"/></vehicle></routes>\n'
    )
    (out / "bound.sumocfg").write_text(
        '<configuration><input><net-file value="line.net.xml"/><route-files value="veh0.rou.xml"/></input>'
        '<time><begin value="0"/><end value="60"/><step-length value="0.1"/></time></configuration>\n'
    )
    return out


def scenario(tmp_path: Path, name: str) -> Path:
    """A copy of the corpus (the importer writes its files into .sbsim/ beside the scenario)."""
    shutil.copytree(CORPUS, tmp_path / "corpus")
    return tmp_path / "corpus" / name


def run_xosc(
    xosc: Path, *extra: str, sumocfg: Path | None = None, sumo: str = ""
) -> tuple[list[dict[str, Any]], FcdTrace]:
    events = xosc.with_suffix(".events.jsonl")
    fcd = xosc.with_suffix(".fcd.xml")
    result = run(
        sumocfg,
        events=events,
        sumo_options=[f"--fcd-output {fcd} --precision 4 {sumo}".strip()],
        extra=["--scenario", str(xosc), *extra],
        timeout=120,
    )
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    return read_events(events), read_fcd(fcd, step=0.1)


def starts(events: list[dict[str, Any]], story: str) -> list[float]:
    return [e["t"] for e in events if e["type"] == "activate" and e["story"] == story]


def test_step_speed_with_parameters_and_the_stop_trigger(road: Path, tmp_path: Path) -> None:
    xosc = scenario(tmp_path, "step-speed.xosc")
    events, fcd = run_xosc(xosc, sumocfg=road / "line.sumocfg")
    assert starts(events, "S/A/Brake") == [5.1], "SimulationTime > 5 is first true at 5.1"
    assert fcd.speed["Ego"][5.0] == pytest.approx(20.0)  # EgoSpeed
    assert fcd.speed["Ego"][8.0] == pytest.approx(10.0)  # SlowSpeed = ${$EgoSpeed / 2}
    assert max(fcd.times) == pytest.approx(12.1), "the storyboard's stop trigger (t > 12) ends the run"
    # --param overrides EgoSpeed, and the expression over it follows.
    xosc2 = xosc.with_name("step-speed-25.xosc")
    shutil.copy(xosc, xosc2)
    events, fcd = run_xosc(xosc2, "--param", "EgoSpeed=25", sumocfg=road / "line.sumocfg")
    assert fcd.speed["Ego"][5.0] == pytest.approx(25.0)
    assert fcd.speed["Ego"][8.0] == pytest.approx(12.5)


def test_maximum_execution_count_two_fires_twice(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(scenario(tmp_path, "twice.xosc"), sumocfg=road / "line.sumocfg")
    up, down = starts(events, "S/A/Up"), starts(events, "S/A/Down")
    assert len(up) == 2 and len(down) == 2
    # Up: Ego appears at 10 m/s (< 11: a rising edge); +4 m/s2 passes 19 m/s after 23 steps.
    assert up[0] == 0.2 and down[0] == pytest.approx(0.2 + 2.3)
    # Each start finds the speed just past its threshold, the step before not.
    for t in up:
        assert fcd.speed["Ego"][t] < 11 and (t == 0.2 or fcd.speed["Ego"][round(t - 0.1, 1)] >= 11)
    for t in down:
        assert fcd.speed["Ego"][t] > 19 and fcd.speed["Ego"][round(t - 0.1, 1)] <= 19
    assert fcd.speed["Ego"][29.0] == pytest.approx(10.0), "after the second Down, Up is complete"


def test_falling_edge_and_storyboard_element_state(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(scenario(tmp_path, "falling.xosc"), sumocfg=road / "line.sumocfg")
    assert starts(events, "S/A/Brake") == [3.1]
    assert starts(events, "S/A/Fell") == [3.8], "speed > 15 turns false at 3.8 (14.4 m/s)"
    assert fcd.speed["Ego"][3.7] == pytest.approx(15.2) and fcd.speed["Ego"][3.8] == pytest.approx(14.4)
    signals = [(e["t"], e["cause"]) for e in events if e["type"] == "signal"]
    assert signals == [(3.8, "fell"), (3.9, "after")], "After starts on Fell's endTransition"


def test_overwrite_stops_the_running_event(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(scenario(tmp_path, "overwrite.xosc"), sumocfg=road / "line.sumocfg")
    assert starts(events, "S/A/Slow") == []
    assert starts(events, "S/A/Fast") == [2.1]
    assert fcd.speed["Ego"][7.0] == pytest.approx(25.0)


def ends(events: list[dict[str, Any]], story: str) -> list[float]:
    return [e["t"] for e in events if e["type"] == "deactivate" and e["story"] == story]


def test_linear_and_cubic_speed_transitions_reach_their_target_and_keep_it(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(scenario(tmp_path, "speed-transitions.xosc"), sumocfg=road / "line.sumocfg")
    assert starts(events, "S/A/Linear") == [2.1] and starts(events, "S/A/Cubic") == [2.1]
    lin, cub = fcd.speed["Lin"], fcd.speed["Cub"]
    one_step = 10 / 4 * 0.1  # m/s the linear change makes in a step
    reached = min(t for t, v in lin.items() if v >= 20 - 1e-3)
    assert reached == pytest.approx(6.1, abs=0.1 + 1e-9), "linear: 20 m/s within one step of 4 s after 2.1"
    assert lin[4.1] == pytest.approx(15.0, abs=one_step), "linear: the midpoint at half time"
    assert lin[3.1] == pytest.approx(12.5, abs=one_step)
    assert cub[4.1] == pytest.approx(15.0, abs=one_step), "cubic: the midpoint speed at half time"
    assert cub[3.1] == pytest.approx(11.5625, abs=0.15), "cubic: 3x^2 - 2x^3 at a quarter, below linear's 12.5"
    assert min(t for t, v in cub.items() if v >= 20 - 1e-3) == pytest.approx(6.1, abs=0.1 + 1e-9)
    # Each event runs while its transition does, then ends; the cars keep 20 m/s (the road allows 33.33).
    for story in ("S/A/Linear", "S/A/Cubic"):
        (end,) = ends(events, story)
        assert end == pytest.approx(6.2, abs=0.1 + 1e-9)
    assert lin[11.0] == pytest.approx(20.0) and cub[11.0] == pytest.approx(20.0)


def test_overwrite_stops_a_running_speed_transition(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(scenario(tmp_path, "overwrite-transition.xosc"), sumocfg=road / "line.sumocfg")
    assert starts(events, "S/A/Rise") == [2.1] and starts(events, "S/A/Hold") == [4.1]
    assert ends(events, "S/A/Rise") == [4.1], "Hold's start stops Rise"
    speed = fcd.speed["Ego"]
    assert speed[4.0] == pytest.approx(10 + 20 * 1.9 / 10, abs=0.2), "Rise ran until then"
    assert max(v for t, v in speed.items() if t > 4.1) < 14.5, "and no further"
    assert speed[11.0] == pytest.approx(12.0)


def test_a_timed_lane_change_takes_its_time_laterally(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(
        scenario(tmp_path, "lane-change.xosc"), sumocfg=road / "line.sumocfg", sumo="--lateral-resolution 0.8"
    )
    appeared = min(fcd.pos["Ego"])
    (start,) = starts(events, "S/A/Change")
    assert start == pytest.approx(appeared + 2.0, abs=0.1 + 1e-9), "40 m driven at 20 m/s"
    y = {t: p[1] for t, p in fcd.pos["Ego"].items()}
    y0 = y[round(start - 0.1, 1)]
    moving = sorted(t for t in y if abs(y[t] - y0) > 1e-3)
    y1 = y[max(y)]
    assert abs(y1 - y0) == pytest.approx(3.2, abs=0.01), "one lane width across"
    done = min(t for t in moving if abs(y[t] - y1) < 1e-3)
    assert done - moving[0] == pytest.approx(3.0, abs=0.1 + 1e-9), "3 s laterally"
    half = round(moving[0] - 0.1 + 1.5, 1)
    assert abs(y[half] - y0) == pytest.approx(1.6, abs=0.2), "sinusoidal: half the way at half the time"
    assert fcd.lane["Ego"][max(y)].endswith("_1")
    (end,) = ends(events, "S/A/Change")
    assert end == pytest.approx(start + 3.1, abs=0.1 + 1e-9), "the event ends when the lane change is done"


def test_a_lane_offset_within_its_max_lateral_acceleration(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(
        scenario(tmp_path, "lane-offset.xosc"), sumocfg=road / "line.sumocfg", sumo="--lateral-resolution 0.8"
    )
    assert starts(events, "S/A/Offset") == [2.1]
    y = {t: p[1] for t, p in fcd.pos["Ego"].items()}
    y0 = y[2.1]
    reached = min(t for t in y if abs(y[t] - y0 - 0.6) < 1e-3)  # 0.6 m to the left (+y on this road)
    assert reached == pytest.approx(2.1 + 1.8, abs=0.1 + 1e-9), "T = sqrt(6 d / a) = 1.73 s"
    assert y[3.0] - y0 == pytest.approx(0.6 * (3 * 0.52**2 - 2 * 0.52**3), abs=0.05), "cubic: x = 0.9 / 1.73"
    (end,) = ends(events, "S/A/Offset")
    assert end == pytest.approx(reached + 0.1, abs=0.1 + 1e-9), "the event ends when the offset is reached"


def test_cut_in_in_the_shape_of_the_asam_example(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(
        scenario(tmp_path, "cut-in.xosc"), sumocfg=road / "line.sumocfg", sumo="--lateral-resolution 0.8"
    )
    ego, adv = fcd.pos["Ego"], fcd.pos["Adversary"]
    appeared = min(adv)
    gap = {t: adv[t][0] - ego[t][0] - 5.0 for t in adv if t in ego}  # freespace, front bumpers, both 5 m
    (cut,) = starts(events, "S/A/CutIn")
    assert cut == pytest.approx(appeared + 5.0, abs=0.2), "15 m ahead after 50 m of relative travel at 10 m/s"
    assert gap[cut] >= 15 > gap[round(cut - 0.1, 1)], "the falling edge of 'less than 15 m'"
    (cut_end,) = ends(events, "S/A/CutIn")
    assert cut_end == pytest.approx(cut + 2.1, abs=0.1 + 1e-9), "a 2 s lane change"
    assert fcd.lane["Adversary"][cut_end] == fcd.lane["Ego"][cut_end]
    assert adv[cut_end][1] == pytest.approx(ego[cut_end][1], abs=0.01), "in the centre of Ego's lane"
    assert starts(events, "S/A/Slow") == [cut_end], "Slow starts on CutIn's endTransition"
    speed = fcd.speed["Adversary"]
    slowed = min(t for t, v in speed.items() if t > cut_end and v <= 15 + 1e-3)
    assert slowed == pytest.approx(cut_end + 7.5, abs=0.2), "30 -> 15 m/s at 2 m/s^2"
    last = max(gap)
    (slow_end,) = ends(events, "S/A/Slow")
    assert slow_end == pytest.approx(cut_end + 7.6, abs=0.1 + 1e-9), "Slow ends the step after it reached 15 m/s"
    assert speed[last] == pytest.approx(15.0, abs=0.01), "and Adversary keeps 15 m/s"
    assert fcd.speed["Ego"][last] < 16, "Ego (SUMO's driver, 20 m/s) slowed down behind it"
    assert min(g for t, g in gap.items() if t >= cut) > 0, "no collision once it is ahead"


def test_opendrive_highway_and_a_catalog_vehicle(tmp_path: Path) -> None:
    xosc = scenario(tmp_path, "slow-lead.xosc")
    events, fcd = run_xosc(xosc)
    # OpenDRIVE road 1, lane -1 (next to the centre line) is SUMO's leftmost lane of edge -1.
    assert fcd.lane["Ego"][0.2] == "-1_1" and fcd.pos["Ego"][0.2][0] == pytest.approx(50.0)
    assert fcd.pos["Lead"][0.2][0] == pytest.approx(150.0)  # RoadPosition s=150, t=-1.75: lane -1
    assert fcd.lane["Lead"][0.2] == "-1_1"
    assert fcd.type["Lead"][0.2] == "xosc_Lead"
    (follow,) = starts(events, "S/A/Follow")
    # Between the centres: Lead 12 m, Ego 5 m long, so 3.5 m less than between the front bumpers.
    gap = fcd.pos["Lead"][follow][0] - fcd.pos["Ego"][follow][0] - 3.5
    before = round(follow - 0.1, 1)
    assert gap <= 40 < fcd.pos["Lead"][before][0] - fcd.pos["Ego"][before][0] - 3.5
    cache = xosc.parent / ".sbsim"
    assert "origId" in (cache / "highway.net.xml").read_text(), "converted with --output.original-names"
    (types,) = cache.glob("*.vtypes.add.xml")
    assert '<vType id="xosc_Lead" vClass="truck" length="12" width="2.5"' in types.read_text()


def test_a_catalog_maneuver_with_its_parameters_assigned(road: Path, tmp_path: Path) -> None:
    xosc = scenario(tmp_path, "catalog-maneuver.xosc")
    events, fcd = run_xosc(xosc, sumocfg=road / "line.sumocfg")
    assert starts(events, "S/A/Brake") == [4.1], "At = 4 assigned (the catalog's default is 5)"
    assert fcd.speed["Ego"][4.1] == pytest.approx(20.0)
    assert fcd.speed["Ego"][4.8] == pytest.approx(15.0), "TargetSpeed = 15 assigned (the default is 10)"
    # A reference to no entry names the catalog and the reference's line; an element the importer cannot
    # run inside a catalog names the catalog's file.
    xosc.write_text(xosc.read_text().replace('entryName="SlowDown"', 'entryName="SpeedUp"'))
    result = run(road / "line.sumocfg", extra=["--scenario", str(xosc)], timeout=120)
    assert_bad_input(result, f"{xosc}:", "<CatalogReference>", "catalog 'ManeuverCatalog' has no maneuver 'SpeedUp'")
    xosc.write_text(xosc.read_text().replace('entryName="SpeedUp"', 'entryName="SlowDown"'))
    catalog = xosc.parent / "catalogs" / "ManeuverCatalog.xosc"
    catalog.write_text(catalog.read_text().replace("SimulationTimeCondition", "TimeOfDayCondition"))
    result = run(road / "line.sumocfg", extra=["--scenario", str(xosc)], timeout=120)
    assert "ManeuverCatalog.xosc:" in assert_bad_input(result, "unsupported")


def test_bind_makes_a_sumo_vehicle_the_entity(road: Path, tmp_path: Path) -> None:
    events, fcd = run_xosc(scenario(tmp_path, "step-speed.xosc"), "--bind", "Ego=veh0", sumocfg=road / "bound.sumocfg")
    assert "Ego" not in fcd.speed
    assert starts(events, "S/A/Brake") == [5.1]
    assert [e["vehicle"] for e in events if e["story"] == "S/A/Brake" and e["type"] == "activate"] == ["veh0"]
    assert fcd.speed["veh0"][5.0] == pytest.approx(20.0) and fcd.speed["veh0"][8.0] == pytest.approx(10.0)


def test_check_prints_the_imported_stories(road: Path, tmp_path: Path) -> None:
    xosc = scenario(tmp_path, "falling.xosc")
    result = run(road / "line.sumocfg", extra=["check", "--scenario", str(xosc)], timeout=120)
    assert result.returncode == 0, result.stderr
    assert "story 'S/A/Fell'" in result.stdout
    assert "ElementCondition(Event 'Fell', actors Ego; start (fast falling))" in result.stdout
    assert "EntityCondition(Ego)" in result.stdout
    assert "SignalEffect" in result.stdout


def test_unsupported_elements_are_one_error_with_their_lines(road: Path, tmp_path: Path) -> None:
    xosc = scenario(tmp_path, "unsupported.xosc")
    result = run(road / "line.sumocfg", extra=["--scenario", str(xosc)], timeout=120)
    line = assert_bad_input(result, "3 unsupported OpenSCENARIO elements", "<Pedestrian> (line 18)")
    assert "<LaneChangeActionDynamics> (line 43): followingMode 'follow' here" in line
    assert "<TimeOfDayCondition> (line 59)" in line


@pytest.mark.parametrize(
    ("edit", "needles"),
    [
        (lambda s: s.replace("</Storyboard>", "</Storybord>"), ["not well-formed XML"]),
        (
            lambda s: s.replace('conditionEdge="rising"', 'conditionEdge="sometimes"', 1),
            ["fails the ASAM schema", "conditionEdge"],
        ),
        (lambda s: s.replace('value="$EgoSpeed"', 'value="$Nope"'), ["no parameter 'Nope' is declared"]),
        (lambda s: s.replace('roadId="A0B0"', 'roadId="Z9"'), ["road 'Z9' lane 0 maps to no SUMO lane"]),
    ],
)
def test_malformed_scenarios_are_one_line_with_their_place(
    road: Path, tmp_path: Path, edit: Callable[[str], str], needles: list[str]
) -> None:
    xosc = scenario(tmp_path, "step-speed.xosc")
    xosc.write_text(edit(xosc.read_text()))
    result = run(road / "line.sumocfg", extra=["--scenario", str(xosc)], timeout=120)
    line = assert_bad_input(result, str(xosc), *needles)
    assert re.search(re.escape(str(xosc)) + r":\d+:", line), "the line of the element"


def test_param_of_the_wrong_type_and_bind_of_no_entity(road: Path, tmp_path: Path) -> None:
    xosc = scenario(tmp_path, "step-speed.xosc")
    cfg = road / "line.sumocfg"
    assert_bad_input(
        run(cfg, extra=["--scenario", str(xosc), "--param", "EgoSpeed=fast"]), "--param EgoSpeed", "double"
    )
    assert_bad_input(run(cfg, extra=["--scenario", str(xosc), "--bind", "Nobody=veh0"]), "no entity 'Nobody'")
    assert_bad_input(run(cfg, extra=["--bind", "Ego=veh0"]), "--bind", "--scenario")


def test_the_prepared_files_are_reused(road: Path, tmp_path: Path) -> None:
    from storyboard.openscenario.prepare import prepare

    xosc = scenario(tmp_path, "step-speed.xosc")
    first = prepare(xosc, road / "line.sumocfg", {}, {})
    second = prepare(xosc, road / "line.sumocfg", {}, {})
    assert first == second
    other = prepare(xosc, road / "line.sumocfg", {"EgoSpeed": "30"}, {})
    assert json.dumps(other) == json.dumps(first), "types do not depend on EgoSpeed below the limit"


def test_every_mapped_condition(road: Path, tmp_path: Path) -> None:
    xosc = scenario(tmp_path, "conditions.xosc")
    events, fcd = run_xosc(xosc, sumocfg=road / "line.sumocfg")
    fired = {e["cause"]: e["t"] for e in events if e["type"] == "signal"}
    assert fired["Rel"] == 0.2 and fired["Param"] == 0.2, "true when the storyboard starts"
    assert "Stand" not in fired and "Crash" not in fired, "Ego never stands, nobody collides"

    def x(vehicle: str, t: float) -> float:
        return fcd.pos[vehicle][round(t, 1)][0]

    def before(t: float) -> float:
        return round(t - 0.1, 1)

    assert x("Other", 0.2) == pytest.approx(110.0), "RelativeLanePosition: 100 m ahead of Ego"
    # Each fired at the first step its condition held (front bumpers, 0.1 s steps).
    reach = fired["Reach"]
    assert abs(x("Ego", reach) - 150) <= 2 < abs(x("Ego", before(reach)) - 150)
    near = fired["Near"]
    assert x("Other", near) - x("Ego", near) <= 30 < x("Other", before(near)) - x("Ego", before(near))
    point = fired["Point"]
    assert abs(x("Ego", point) - 300) <= 10 < abs(x("Ego", before(point)) - 300)
    # Longitudinal free space to a point (300, on lane 0): from Ego's front bumper, 300 - x < 20.
    ahead = fired["Ahead"]
    assert 300 - x("Ego", ahead) < 20 <= 300 - x("Ego", before(ahead))
    brake = fired["Brake"]
    assert fcd.speed["Ego"][brake] - fcd.speed["Ego"][before(brake)] < -0.2  # < -2 m/s2 over 0.1 s
    assert {lane[-2:] for lane in fcd.lane["Ego"].values()} == {"_0"}, "an entity keeps its lane (behind Other)"
    # AddEntityAction at t > 3 s: Late departs at the next step, where the action put it.
    assert min(fcd.speed["Late"]) == 3.2 and fcd.lane["Late"][3.2] == "B0C0_1"
    assert fcd.pos["Late"][3.2][0] == pytest.approx(510.0)

    result = run(road / "line.sumocfg", extra=["check", "--scenario", str(xosc)], timeout=120)
    assert result.returncode == 0, result.stderr
    for mapped in (
        "SpeedDifferenceConditionFaster(5 m/s)",
        "HeadwayCondition(1.5 s)",
        "TtcCondition(4 s",
        "AccelerationConditionLess(-2",
        "StandstillCondition(1 s)",
        "CollisionCondition",
        "RelativeDistanceCondition(vehicle Other, cartesian reference points, lessThan 30 m)",
        "PositionDistanceCondition((300, ",
        "longitudinal freespace, lessThan 20 m)",
        "SpawnEffect('Late', route B0C0 C0D0, type xosc_Late)",
        "story 'S/A/Add (world)'",
    ):
        assert mapped in result.stdout, f"{mapped!r} not in:\n{result.stdout}"


def test_a_study_sweeps_a_declared_parameter(road: Path, tmp_path: Path) -> None:
    from sbsim import study

    xosc = scenario(tmp_path, "step-speed.xosc")
    spec = study.StudySpec.from_dict(
        {
            "sumocfg": str(road / "line.sumocfg"),
            "scenario": str(xosc),
            "seeds": [1],
            "args": ["--", "--fcd-output", "{run_dir}/fcd.xml"],
            "parameters": {"EgoSpeed": [16, 24]},
            "outputs": {"directory": str(tmp_path / "results")},
        },
        base=tmp_path,
    )
    slow = {}
    for r in spec.runs():
        row = study.execute(spec, r, str(executable()))
        assert row["exit_code"] == 0, row["stderr_tail"]
        folder = spec.directory / "runs" / r.id
        assert "warning" not in (folder / "stderr.txt").read_text(), "the parameter was read"
        slow[r.parameters[0][1]] = read_fcd(folder / "fcd.xml", step=0.1).speed["Ego"][8.0]
    assert slow == {16: pytest.approx(8.0), 24: pytest.approx(12.0)}, "SlowSpeed = EgoSpeed / 2 in each run"


def test_an_event_raises_a_denm_through_a_custom_command(road: Path, tmp_path: Path) -> None:
    xosc = scenario(tmp_path, "emergency-brake.xosc")
    messages = tmp_path / "messages.jsonl"
    events, fcd = run_xosc(
        xosc,
        "--services",
        str(xosc.with_name("emergency-brake.services.xml")),
        "--messages",
        str(messages),
        sumocfg=road / "line.sumocfg",
    )
    signals = [(e["t"], e["vehicle"], e["cause"]) for e in events if e["type"] == "signal"]
    assert signals == [(5.1, "Lead", "hard braking")]
    lines = [json.loads(line) for line in messages.read_text().splitlines()]
    denms = [m for m in lines if m.get("type") == "DENM"]
    first = next(m for m in denms if m["event"] == "tx")
    assert first["station"] == "Lead" and first["cause"] == 99 and 5.1 <= first["t"] < 5.2
    assert any(m["event"] == "rx" and m["station"] == "Ego" and m["sender"] == "Lead" for m in denms)
    assert {m["station"] for m in lines if m.get("type") == "CAM" and m["event"] == "tx"} == {"Ego", "Lead"}
    # Lead stops (20 m/s at 9 m/s2: in 2.3 s); Ego brakes for it by itself and stays behind.
    assert fcd.speed["Lead"][8.0] == 0.0
    assert fcd.pos["Ego"][15.0][0] < fcd.pos["Lead"][15.0][0] - 5
    if keep := os.environ.get("SBSIM_XOSC_PICTURE"):
        plot_emergency_brake(fcd, lines, Path(keep))


def plot_emergency_brake(fcd: FcdTrace, messages: list[dict[str, Any]], out: Path) -> None:
    """The README's figure: both speeds, the gap, and when the DENM went out and was heard."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (speed, gap) = plt.subplots(2, 1, sharex=True, figsize=(7, 4.5))
    for vehicle in ("Ego", "Lead"):
        times = sorted(fcd.speed[vehicle])
        speed.plot(times, [fcd.speed[vehicle][t] for t in times], label=vehicle)
    times = sorted(set(fcd.pos["Ego"]) & set(fcd.pos["Lead"]))
    gap.plot(times, [fcd.pos["Lead"][t][0] - fcd.pos["Ego"][t][0] for t in times], color="grey")
    tx = min(m["t"] for m in messages if m.get("type") == "DENM" and m["event"] == "tx")
    rx = min(m["t"] for m in messages if m.get("type") == "DENM" and m["event"] == "rx" and m["station"] == "Ego")
    cams = [m["t"] for m in messages if m.get("type") == "CAM" and m["event"] == "tx"]
    for axis in (speed, gap):
        axis.axvline(tx, color="red", linestyle="--", linewidth=1)
    speed.text(tx + 0.2, 10, f"DENM: Lead sends at {tx:.3f} s,\nEgo hears at {rx:.3f} s", color="red")
    speed.plot(cams, [0.5] * len(cams), "|", color="black", markersize=6, label="CAM sent")
    speed.set_ylabel("speed (m/s)")
    speed.legend(loc="center left")
    gap.set_ylabel("gap Lead - Ego (m)")
    gap.set_xlabel("time (s)")
    fig.suptitle("emergency-brake.xosc: Lead brakes at t > 5 s and raises a DENM")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


def test_road_positions_find_their_lane_from_the_opendrive_widths() -> None:
    from storyboard.openscenario.errors import ScenarioError
    from storyboard.openscenario.opendrive import lane_at

    xodr = CORPUS / "highway.xodr"  # road 1: two right lanes of 3.5 m
    assert lane_at(xodr, "1", 500, -1.75, "here") == -1
    assert lane_at(xodr, "1", 500, -3.5, "here") == -1
    assert lane_at(xodr, "1", 500, -5.0, "here") == -2
    with pytest.raises(ScenarioError, match="t=-7.1 is off road '1' at s=500"):
        lane_at(xodr, "1", 500, -7.1, "here")
    with pytest.raises(ScenarioError, match="no road '9'"):
        lane_at(xodr, "9", 0, -1, "here")


def test_a_storyboard_element_state_of_no_element_is_one_line(road: Path, tmp_path: Path) -> None:
    xosc = scenario(tmp_path, "falling.xosc")
    xosc.write_text(xosc.read_text().replace('storyboardElementRef="Fell"', 'storyboardElementRef="Fall"'))
    result = run(road / "line.sumocfg", extra=["--scenario", str(xosc)], timeout=120)
    assert_bad_input(result, f"{xosc}:", "<StoryboardElementStateCondition>", "no event named 'Fall'")


def test_parameters_change_in_the_run(road: Path, tmp_path: Path) -> None:
    events, _ = run_xosc(scenario(tmp_path, "parameters.xosc"), sumocfg=road / "line.sumocfg")
    assert starts(events, "S/A/Bump (world)") == [2.1, 2.3, 2.5, 2.7, 2.9]
    signals = [(e["t"], e["cause"]) for e in events if e["type"] == "signal"]
    assert signals == [(2.6, "three"), (4.2, "storm")], "a change is seen the step after"


def test_delete_entity_takes_the_vehicle_out(road: Path, tmp_path: Path) -> None:
    xosc = scenario(tmp_path, "step-speed.xosc")
    delete = '<GlobalAction><EntityAction entityRef="Ego"><DeleteEntityAction/></EntityAction></GlobalAction>'
    text = xosc.read_text()
    slow = text[text.index("<PrivateAction>", text.index('<Action name="slow">')) : text.index("</Action>")]
    xosc.write_text(text.replace(slow, delete))
    # veh0 (bound.sumocfg's) keeps the run going once Ego is gone.
    events, fcd = run_xosc(xosc, sumocfg=road / "bound.sumocfg")
    assert starts(events, "S/A/Brake (world)") == [5.1]
    assert max(fcd.speed["Ego"]) == 5.1, "removed in the step of 5.1 s: not in the FCD after"
    left = [e for e in events if e["type"] == "deactivate" and e["vehicle"] == "Ego"]
    assert [(e["t"], e["story"], e["reason"]) for e in left] == [(5.2, "Init/Ego", "vehicle_left")]
    assert max(fcd.speed["veh0"]) == 12.1


def test_delay_skip_and_an_acts_stop_trigger(road: Path, tmp_path: Path) -> None:
    events, _ = run_xosc(scenario(tmp_path, "timing.xosc"), sumocfg=road / "line.sumocfg")
    signals = [(e["t"], e["cause"]) for e in events if e["type"] == "signal"]
    assert signals == [
        (3.1, "Late"),  # t > 1 first at 1.1, seen 2 s later
        (4.1, "Busy"),
        (4.2, "Polite"),  # skipped at 4.1 (Busy runs), starts as Busy ends
        (4.3, "Busy"),
        (4.4, "Polite"),
        (4.5, "Busy"),
    ], "the act's stop trigger (t > 4.5) ends both at 4.6"
    (act_end,) = [e for e in events if e["type"] == "deactivate" and e["story"] == "S/A"]
    assert act_end["t"] == 4.6


def test_the_cut_in_example_runs_among_traffic_with_cams(tmp_path: Path) -> None:
    example = Path(__file__).resolve().parents[2] / "examples" / "openscenario-cut-in"
    xosc = tmp_path / "cut-in.xosc"  # the importer writes .sbsim/ beside it: not into the repository
    shutil.copy(example / "cut-in.xosc", xosc)
    messages = tmp_path / "messages.jsonl"
    events, fcd = run_xosc(
        xosc,
        "--services",
        str(example / "services.xml"),
        "--messages",
        str(messages),
        sumocfg=example / "cut-in.sumocfg",
    )
    # Both appear at 0.2 s; Adversary is 15 m ahead (freespace) after 100 + 5 + 15 m of relative travel at 10 m/s.
    (cut,) = starts(events, "S/A/CutIn")
    assert cut == pytest.approx(12.2, abs=0.11)
    (cut_end,) = ends(events, "S/A/CutIn")
    assert cut_end == pytest.approx(cut + 2.0, abs=0.11), "a 2 s lane change"
    assert fcd.lane["Adversary"][cut_end] == fcd.lane["Ego"][cut_end]
    assert fcd.pos["Adversary"][cut_end][1] == pytest.approx(fcd.pos["Ego"][cut_end][1], abs=0.01)
    assert starts(events, "S/A/Slow") == [cut_end]
    # The motorway's own traffic runs around them, and the CAMs reach the entities.
    assert len(fcd.speed) > 10
    lines = [json.loads(line) for line in messages.read_text().splitlines()]
    heard = {m["sender"] for m in lines if m["event"] == "rx" and m["type"] == "CAM" and m["station"] == "Ego"}
    assert "Adversary" in heard and len(heard) > 5
