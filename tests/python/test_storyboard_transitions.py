"""OpenSCENARIO-grade transitions on a straight three-lane road, sampled per 0.1 s step from SUMO's FCD:
SpeedChangeEffect (shapes by time, rate and distance; relative targets), LaneChangeEffect (a lateral
manoeuvre over a given time through SUMO's sublane model) and LaneOffsetEffect. Expected values are
computed by hand from the shapes; the vehicles are SUMO's."""

from __future__ import annotations

import itertools
import math
import subprocess
from collections.abc import Callable
from pathlib import Path

import pytest
from sbsim.sumo import sumo_binary, sumo_environment
from sbsim_helpers import FcdTrace, StoryRun, read_fcd, run_story

STEP = 0.1
#: The road runs along x; lane i's centre lies at y = LANE_Y[i] (3.2 m lanes), so y is the lateral position.
LANE_Y = (-8.0, -4.8, -1.6)
START = 5.0  # s: when the stories act


@pytest.fixture(scope="module")
def road_cfg(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A straight 3 km road of three lanes (limit 40 m/s); "ego" on lane 0 keeping 12 m/s, "lead" on
    lane 1 keeping 20 m/s and "slow" on lane 2 keeping 15 m/s (their speed factors), both so far ahead that
    ego never reaches them here; step 0.1 s, sublane model (lateral resolution 0.8 m)."""
    out = tmp_path_factory.mktemp("road")
    (out / "road.nod.xml").write_text(
        '<nodes><node id="a" x="0" y="0"/><node id="b" x="3000" y="0"/></nodes>\n', encoding="utf-8"
    )
    (out / "road.edg.xml").write_text(
        '<edges><edge id="ab" from="a" to="b" numLanes="3" speed="40"/></edges>\n', encoding="utf-8"
    )
    subprocess.run(
        [sumo_binary("netconvert"), "-n", "road.nod.xml", "-e", "road.edg.xml", "-o", "road.net.xml"],
        cwd=out,
        env=sumo_environment(),
        capture_output=True,
        check=True,
    )
    (out / "road.rou.xml").write_text(
        """<routes>
    <vType id="ego" maxSpeed="50" accel="4" decel="8" emergencyDecel="9" sigma="0" speedDev="0" speedFactor="0.3"/>
    <vType id="lead" maxSpeed="50" accel="4" decel="8" emergencyDecel="9" sigma="0" speedDev="0" speedFactor="0.5"/>
    <vType id="slow" maxSpeed="50" accel="4" decel="8" emergencyDecel="9" sigma="0" speedDev="0" speedFactor="0.375"/>
    <route id="r" edges="ab"/>
    <vehicle id="ego" type="ego" route="r" depart="0" departLane="0" departSpeed="12" departPos="10"/>
    <vehicle id="lead" type="lead" route="r" depart="0" departLane="1" departSpeed="20" departPos="1000"/>
    <vehicle id="slow" type="slow" route="r" depart="0" departLane="2" departSpeed="15" departPos="1200"/>
</routes>
""",
        encoding="utf-8",
    )
    cfg = out / "road.sumocfg"
    cfg.write_text(
        """<configuration>
    <input><net-file value="road.net.xml"/><route-files value="road.rou.xml"/></input>
    <time><begin value="0"/><end value="60"/><step-length value="0.1"/></time>
    <processing><lateral-resolution value="0.8"/></processing>
    <report><no-step-log value="true"/><duration-log.disable value="true"/></report>
</configuration>
""",
        encoding="utf-8",
    )
    return cfg


def story_run(cfg: Path, directory: Path, effects: str, *, end: float = 25.0) -> StoryRun:
    """One story on "ego" from START on: `effects`, the Python list of its effects."""
    source = f"""
        import storyboard as sb
        def createStories(board):
            board.registerStory(sb.Story(sb.all_of(sb.CarSetCondition("ego"), sb.TimeCondition({START})),
                                         {effects}, "act"))
    """
    return run_story(cfg, source, directory, end=end, fcd=True)


def fcd(run: StoryRun) -> FcdTrace:
    """The run's FCD on sbsim's clock for this scenario's 0.1 s step."""
    return read_fcd(run.story.with_suffix(".fcd.xml"), step=STEP)


def activation(run: StoryRun) -> float:
    (event,) = run.of(type="activate", story="act")
    return float(event["t"])


def speeds_from(run: StoryRun, vehicle: str = "ego") -> dict[float, float]:
    """`vehicle`'s speed by seconds since the story activated."""
    t0 = activation(run)
    return {round(t - t0, 3): v for t, v in fcd(run).speed[vehicle].items() if t >= t0 - 1e-9}


@pytest.mark.parametrize(
    ("shape", "expected"),
    [
        ("linear", lambda x: x),
        ("cubic", lambda x: 3 * x * x - 2 * x**3),
        ("sinusoidal", lambda x: 0.5 - 0.5 * math.cos(math.pi * x)),
    ],
)
def test_speed_change_by_time_follows_its_shape(
    road_cfg: Path, tmp_path: Path, shape: str, expected: Callable[[float], float]
) -> None:
    run = story_run(road_cfg, tmp_path, f'[sb.SpeedChangeEffect(20.0, "{shape}", "time", 4.0)]')
    speeds = speeds_from(run)
    start = speeds[0.0]
    assert start == pytest.approx(12.0, abs=1e-3)  # the vehicle's own speed at activation
    for k in range(0, 41):
        t = round(k * STEP, 3)
        want = start + (20.0 - start) * expected(t / 4.0)
        assert speeds[t] == pytest.approx(want, abs=1e-3), f"{shape} at {t} s"
    # The target within one step of 4 s, held after while the story is active.
    assert speeds[4.0] == pytest.approx(20.0, abs=1e-3)
    assert speeds[3.9] < 20.0 - 1e-3
    assert all(abs(v - 20.0) < 1e-3 for t, v in speeds.items() if 4.0 <= t <= 12.0)
    if shape == "cubic":
        assert speeds[2.0] == pytest.approx((start + 20.0) / 2, abs=1e-3), "midpoint speed at half time"


def test_speed_change_by_rate_takes_delta_over_rate(road_cfg: Path, tmp_path: Path) -> None:
    run = story_run(road_cfg, tmp_path, '[sb.SpeedChangeEffect(30.0, "linear", "rate", 2.5)]')
    speeds = speeds_from(run)
    start = speeds[0.0]
    duration = (30.0 - start) / 2.5
    reached = min(t for t, v in speeds.items() if v >= 30.0 - 1e-3)
    assert abs(reached - duration) <= STEP + 1e-9, (reached, duration)
    assert speeds[round(duration / 2, 1)] == pytest.approx(start + 2.5 * round(duration / 2, 1), abs=1e-3)


def test_speed_change_by_distance_reaches_the_target_after_the_distance(road_cfg: Path, tmp_path: Path) -> None:
    run = story_run(road_cfg, tmp_path, '[sb.SpeedChangeEffect(25.0, "linear", "distance", 100.0)]')
    t0 = activation(run)
    x = {round(t - t0, 3): p[0] for t, p in fcd(run).pos["ego"].items() if t >= t0 - 1e-9}
    speeds = speeds_from(run)
    reached = min(t for t, v in speeds.items() if v >= 25.0 - 1e-3)
    driven = x[reached] - x[0.0]
    assert abs(driven - 100.0) <= 25.0 * STEP + 1e-6, driven  # within one step's drive
    # Linear in distance: halfway there, the speed is halfway.
    half = min(t for t in x if x[t] - x[0.0] >= 50.0)
    assert speeds[half] == pytest.approx((speeds[0.0] + 25.0) / 2, abs=0.5)


def test_speed_change_relative_to_another_vehicle(road_cfg: Path, tmp_path: Path) -> None:
    # "lead" drives 20 m/s; ego goes to lead's speed - 5 m/s at once, and to 1.5 x slow's speed by then.
    run = story_run(road_cfg, tmp_path, '[sb.SpeedChangeEffect(-5.0, relative_to="lead", continuous=True)]', end=12)
    speeds = speeds_from(run)
    lead = speeds_from(run, "lead")
    for t in (0.1, 1.0, 3.0, 6.0):
        assert speeds[t] == pytest.approx(lead[round(t - STEP, 3)] - 5.0, abs=1e-3), t
    run = story_run(
        road_cfg,
        tmp_path / "factor",
        '[sb.SpeedChangeEffect(1.5, "linear", "time", 2.0, relative_to="slow", value_type="factor")]',
        end=12,
    )
    speeds = speeds_from(run)
    slow_then = speeds_from(run, "slow")[0.0]
    assert speeds[2.0] == pytest.approx(1.5 * slow_then, abs=1e-3)


def test_speed_control_goes_back_to_sumo_when_the_story_ends(road_cfg: Path, tmp_path: Path) -> None:
    source = f"""
        import storyboard as sb
        def createStories(board):
            board.registerStory(sb.Story(sb.all_of(sb.CarSetCondition("ego"), sb.TimeCondition({START}, {START + 5})),
                                         [sb.SpeedChangeEffect(2.0, "linear", "time", 2.0)], "act"))
    """
    run = run_story(road_cfg, source, tmp_path, end=25, fcd=True)
    speeds = speeds_from(run)
    assert speeds[3.0] == pytest.approx(2.0, abs=1e-3)
    # Released: SUMO's driver accelerates (at most its 4 m/s²) to its own 12 m/s again.
    assert speeds[10.0] > 10.0
    assert speeds[15.0] == pytest.approx(12.0, abs=1e-3)
    after = [v for t, v in sorted(speeds.items()) if t >= 5.0]
    assert all(b - a <= 4.0 * STEP + 1e-3 for a, b in itertools.pairwise(after))


def lateral_from(run: StoryRun) -> dict[float, float]:
    """ego's lateral position (m across the road, its y) by seconds since the story activated."""
    t0 = activation(run)
    return {round(t - t0, 3): p[1] for t, p in fcd(run).pos["ego"].items() if t >= t0 - 1e-9}


def test_lane_change_of_three_seconds_takes_three_seconds_laterally(road_cfg: Path, tmp_path: Path) -> None:
    run = story_run(road_cfg, tmp_path, '[sb.LaneChangeEffect(1, "sinusoidal", "time", 3.0)]')
    y = lateral_from(run)
    assert y[0.0] == pytest.approx(LANE_Y[0], abs=1e-3)
    for k in range(0, 31):
        t = round(k * STEP, 3)
        want = LANE_Y[0] + 3.2 * (0.5 - 0.5 * math.cos(math.pi * t / 3.0))
        assert y[t] == pytest.approx(want, abs=1e-3), t
    assert y[2.9] < LANE_Y[1] - 1e-3, "not there before 3 s"
    assert all(v == pytest.approx(LANE_Y[1], abs=1e-3) for t, v in y.items() if 3.0 <= t <= 15.0), "held after"
    assert fcd(run).lane["ego"][round(activation(run) + 5.0, 3)] == "ab_1"


def test_relative_lane_change_and_lane_offset(road_cfg: Path, tmp_path: Path) -> None:
    run = story_run(road_cfg, tmp_path, '[sb.LaneChangeEffect(2, "linear", "time", 4.0, relative=True)]')
    y = lateral_from(run)
    assert y[2.0] == pytest.approx(LANE_Y[1], abs=1e-3)
    assert y[4.0] == pytest.approx(LANE_Y[2], abs=1e-3)
    run = story_run(road_cfg, tmp_path / "offset", '[sb.LaneOffsetEffect(0.6, "cubic", duration=2.0)]')
    y = lateral_from(run)
    assert y[1.0] == pytest.approx(LANE_Y[0] + 0.3, abs=1e-3)
    assert all(v == pytest.approx(LANE_Y[0] + 0.6, abs=1e-3) for t, v in y.items() if 2.0 <= t <= 15.0)


def test_lateral_transitions_need_the_sublane_model(road_cfg: Path, tmp_path: Path) -> None:
    source = f"""
        import storyboard as sb
        def createStories(board):
            board.registerStory(sb.Story(sb.all_of(sb.CarSetCondition("ego"), sb.TimeCondition({START})),
                                         [sb.LaneChangeEffect(1, "linear", "time", 3.0)], "act"))
    """
    run = run_story(road_cfg, source, tmp_path, end=10, sumo_options=("--lateral-resolution -1",), check=False)
    assert run.returncode == 2
    assert "sublane model" in run.result.stderr and "act" in run.result.stderr


CONDITIONS_STORY = """
    import storyboard as sb
    def createStories(board):
        ego = sb.CarSetCondition("ego")
        board.registerStory(sb.Story(sb.all_of(ego, sb.TraveledDistanceCondition(120)), [], "traveled"))
        behind = sb.RelativeDistanceCondition("lead", 1000, "greaterThan", "longitudinal", freespace=True)
        board.registerStory(sb.Story(sb.all_of(ego, behind), [], "behind"))
        apart = sb.RelativeDistanceCondition("slow", 1195, "greaterThan")
        board.registerStory(sb.Story(sb.all_of(ego, apart), [], "slow"))
"""


def test_traveled_and_relative_distance_conditions_on_sumo_positions(road_cfg: Path, tmp_path: Path) -> None:
    run = run_story(road_cfg, CONDITIONS_STORY, tmp_path, end=20, fcd=True)
    trace = fcd(run)
    x = {v: {t: p[0] for t, p in trace.pos[v].items()} for v in ("ego", "lead", "slow")}
    y = {v: {t: p[1] for t, p in trace.pos[v].items()} for v in ("ego", "lead", "slow")}
    start = x["ego"][min(x["ego"])]  # where it departed: nothing driven yet
    # Each activates at the first step whose positions (front bumpers, on a straight road along x) say so.
    traveled = min(t for t in sorted(x["ego"]) if x["ego"][t] - start >= 120 - 1e-6)
    assert run.of(type="activate", story="traveled")[0]["t"] == pytest.approx(traveled)
    # lead pulls away at 8 m/s. Both 5 m long: the gap is front to front minus lead's length.
    behind = min(t for t in sorted(x["ego"]) if x["lead"][t] - x["ego"][t] - 5.0 > 1000)
    assert run.of(type="activate", story="behind")[0]["t"] == pytest.approx(behind)
    slow = min(
        t for t in sorted(x["ego"]) if math.dist((x["slow"][t], y["slow"][t]), (x["ego"][t], y["ego"][t])) > 1195
    )
    (event,) = run.of(type="activate", story="slow")
    assert event["t"] == pytest.approx(slow)
    assert event.get("others", ["slow"]) == ["slow"]


def test_safe_gap_bounds_the_change_to_the_vehicles_acceleration(road_cfg: Path, tmp_path: Path) -> None:
    exact = speeds_from(story_run(road_cfg, tmp_path, "[sb.SpeedChangeEffect(30.0)]"))
    assert exact[0.1] == pytest.approx(30.0, abs=1e-3), "a step is a step"
    safe = speeds_from(story_run(road_cfg, tmp_path / "safe", "[sb.SpeedChangeEffect(30.0, safe_gap=True)]"))
    # SUMO's safe speed keeps to the vehicle's 4 m/s²: 0.4 m/s per 0.1 s step, 30 m/s after 4.5 s.
    assert safe[0.1] == pytest.approx(12.4, abs=1e-3)
    assert safe[2.0] == pytest.approx(20.0, abs=1e-3)
    assert safe[4.5] == pytest.approx(30.0, abs=1e-3)


def test_sumo_changes_lanes_again_after_a_lane_change_story(road_cfg: Path, tmp_path: Path) -> None:
    source = f"""
        import storyboard as sb
        def createStories(board):
            board.registerStory(sb.Story(sb.all_of(sb.CarSetCondition("ego"), sb.TimeCondition({START}, {START + 6})),
                                         [sb.LaneChangeEffect(2, "linear", "time", 2.0)], "act"))
    """
    run = run_story(road_cfg, source, tmp_path, end=40, fcd=True)
    y = lateral_from(run)
    assert all(v == pytest.approx(LANE_Y[2], abs=1e-3) for t, v in y.items() if 2.0 <= t <= 6.0)
    # Its own lane-change model again (keep right): it leaves the left lane afterwards.
    assert min(v for t, v in y.items() if t > 6.0) < LANE_Y[1] + 1e-3


@pytest.mark.parametrize(
    ("call", "needle"),
    [
        ('sb.SpeedChangeEffect(20, "quadratic", "time", 4)', "shape must be 'step', 'linear', 'cubic' or 'sinusoidal'"),
        ('sb.SpeedChangeEffect(20, "linear", "speed", 4)', "dimension must be 'time', 'distance' or 'rate'"),
        ('sb.SpeedChangeEffect(20, "linear", "time", 0)', "must be > 0 for a 'linear' transition"),
        ("sb.SpeedChangeEffect(-1)", "target speed >= 0"),
        ('sb.SpeedChangeEffect(0.5, value_type="factor")', "need relative_to"),
        ("sb.LaneChangeEffect(-1)", "lane index >= 0"),
        ('sb.LaneChangeEffect(1, relative=True, relative_to="lead")', "not both"),
        ('sb.LaneOffsetEffect(0.5, "cubic")', "duration=seconds or max_lateral_acc"),
        ('sb.RelativeDistanceCondition("lead", 5, "<")', "rule must be 'lessThan'"),
        ('sb.RelativeDistanceCondition("lead", 5, kind="vertical")', "kind must be 'longitudinal'"),
        ("sb.TraveledDistanceCondition(-5)", "must be >= 0 m"),
    ],
)
def test_bad_arguments_are_one_line_errors(road_cfg: Path, tmp_path: Path, call: str, needle: str) -> None:
    source = f"""
        import storyboard as sb
        def createStories(board):
            x = {call}
    """
    run = run_story(road_cfg, source, tmp_path, end=1, check=False)
    assert run.returncode == 2
    assert needle in run.result.stderr, run.result.stderr


def test_lane_change_to_another_vehicles_lane_over_a_distance(road_cfg: Path, tmp_path: Path) -> None:
    run = story_run(road_cfg, tmp_path, '[sb.LaneChangeEffect(0, "linear", "distance", 40.0, relative_to="slow")]')
    trace = fcd(run)
    t0 = activation(run)
    target = LANE_Y[int(trace.lane["slow"][t0].rsplit("_", 1)[1])]  # slow's lane when it activated
    assert target != LANE_Y[0]
    x = {round(t - t0, 3): p[0] for t, p in trace.pos["ego"].items() if t >= t0 - 1e-9}
    y = lateral_from(run)
    for t in sorted(y):
        if t > 8.0:
            break
        share = min(1.0, (x[t] - x[0.0]) / 40.0)  # linear in the distance driven
        assert y[t] == pytest.approx(LANE_Y[0] + (target - LANE_Y[0]) * share, abs=1e-3), t
    assert y[round(40.0 / 12.0 + 0.05, 1)] == pytest.approx(target, abs=1e-3)  # 40 m at 12 m/s
