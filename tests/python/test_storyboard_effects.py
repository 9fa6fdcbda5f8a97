"""Effects: vehicles really obey, measured from SUMO's own FCD output (and SUMO's max speed per step)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from sbsim_helpers import StoryRun, run_story

#: SUMO may need a few steps to brake down to a new cap or to a stop.
BRAKE = 5.0
#: Speed tolerance above a cap [m/s].
TOL = 0.05

CAP = ["veh11", "veh19", "veh23"]  # veh19 is a truck
LOW_THEN_HIGH = ["veh04", "veh24", "veh25"]
HIGH_THEN_LOW = ["veh10", "veh16"]
STOP_TWICE = ["veh00", "veh03", "veh20"]
STOP_ONCE = ["veh22", "veh26", "veh27"]
EMERGENCY = ["veh15"]
EMERGENCY_THEN_STOP = ["veh29"]
WATCHED = CAP + LOW_THEN_HIGH + HIGH_THEN_LOW + STOP_TWICE + STOP_ONCE + EMERGENCY + EMERGENCY_THEN_STOP

ORIGINAL_MAX = {"car": 50.0, "truck": 25.0}  # sbsim.scenarios.grid's vTypes


def _story(max_log: Path) -> str:
    return f"""
    import json
    import numpy as np
    import storyboard
    from storyboard import AndCondition, CarSetCondition, Story, TimeCondition

    WATCHED = set({WATCHED!r})

    class MaxSpeedLog(storyboard.Condition):
        '''Records SUMO's max speed of the watched vehicles at each step; never true.'''
        def test_all(self, snapshot):
            rows = {{vid: float(m) for vid, m in zip(snapshot.ids, snapshot.max_speeds) if vid in WATCHED}}
            with open({str(max_log)!r}, "a") as f:
                f.write(json.dumps([snapshot.time, rows]) + "\\n")
            return np.zeros(len(snapshot), dtype=bool)

    def story(ids, begin, end, effect, name):
        board.registerStory(Story(AndCondition(CarSetCondition(ids), TimeCondition(begin, end)), [effect], name))

    class SpeedModeProbe(storyboard.Effect):
        def __init__(self, label):
            super().__init__()
            self.label = label
        def apply(self, vehicle):
            with open({str(max_log.with_name("modes.txt"))!r}, "a") as f:
                f.write(f"{{vehicle.id}} {{self.label}} {{vehicle.speed_mode}}\\n")
        def remove(self, vehicle):
            pass

    def createStories():
        board.registerStory(Story(MaxSpeedLog(), [], "log"))
        story({EMERGENCY!r}, 40, 40, SpeedModeProbe("before"), "probeBefore")
        story({EMERGENCY!r}, 120, 120, SpeedModeProbe("after"), "probeAfter")
        story({CAP!r}, 60, 150, storyboard.SpeedEffect(5), "cap5")
        story({LOW_THEN_HIGH!r}, 60, 200, storyboard.SpeedEffect(4), "outer4")
        story({LOW_THEN_HIGH!r}, 100, 150, storyboard.SpeedEffect(9), "inner9")
        story({HIGH_THEN_LOW!r}, 60, 120, storyboard.SpeedEffect(9), "first9")
        story({HIGH_THEN_LOW!r}, 80, 200, storyboard.SpeedEffect(4), "second4")
        story({STOP_TWICE!r}, 50, 100, storyboard.StopEffect(), "stopA")
        story({STOP_TWICE!r}, 70, 150, storyboard.StopEffect(), "stopB")
        story({STOP_ONCE!r}, 50, 100, storyboard.StopEffect(), "stopOnly")
        story({EMERGENCY!r}, 50, 100, storyboard.EmergencyStopEffect(), "emergency")
        story({EMERGENCY_THEN_STOP!r}, 50, 100, storyboard.EmergencyStopEffect(), "emergencyA")
        story({EMERGENCY_THEN_STOP!r}, 70, 150, storyboard.StopEffect(), "stopAfterEmergency")
"""


@pytest.fixture(scope="module")
def effects_run(loops_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> tuple[StoryRun, dict]:
    d = tmp_path_factory.mktemp("effects")
    max_log = d / "max_speed.jsonl"
    run = run_story(loops_cfg, _story(max_log), d, end=260, fcd=True)
    max_speed: dict[str, dict[float, float]] = {v: {} for v in WATCHED}
    for line in max_log.read_text().splitlines():
        t, rows = json.loads(line)
        for v, m in rows.items():
            max_speed[v][float(t)] = m
    return run, max_speed


def _types(loops_cfg: Path) -> dict[str, str]:
    import xml.etree.ElementTree as ET

    root = ET.parse(loops_cfg.parent / "routes.rou.xml").getroot()
    return {v.attrib["id"]: v.attrib["type"] for v in root.iter("vehicle")}


def _speeds(run: StoryRun, v: str, t0: float, t1: float) -> dict[float, float]:
    assert run.fcd is not None
    speeds = run.fcd.speeds(v, t0, t1)
    assert len(speeds) == int(t1 - t0) + 1, f"{v} not running throughout [{t0}, {t1}]"
    return speeds


def _assert_capped(run: StoryRun, v: str, t0: float, t1: float, cap: float) -> None:
    over = {t: s for t, s in _speeds(run, v, t0, t1).items() if s > cap + TOL}
    assert not over, f"{v} faster than its cap {cap} m/s: {over}"


def _assert_moves_above(run: StoryRun, v: str, t0: float, t1: float, speed: float) -> None:
    top = max(_speeds(run, v, t0, t1).values())
    assert top > speed, f"{v} never faster than {speed} m/s in [{t0}, {t1}] (top {top})"


def test_all_effect_stories_activated_once_per_vehicle(effects_run: tuple[StoryRun, dict]) -> None:
    run, _ = effects_run
    s = run.result.summary()
    expected = {
        "cap5": 3,
        "outer4": 3,
        "inner9": 3,
        "first9": 2,
        "second4": 2,
        "stopA": 3,
        "stopB": 3,
        "stopOnly": 3,
        "emergency": 1,
        "emergencyA": 1,
        "stopAfterEmergency": 1,
        "log": 0,
        "probeBefore": 1,
        "probeAfter": 1,
    }
    assert {k: int(s[f"activations {k}"]) for k in expected} == expected


@pytest.mark.parametrize("v", CAP)
def test_speed_effect_caps_and_recovers(effects_run: tuple[StoryRun, dict], loops_cfg: Path, v: str) -> None:
    run, max_speed = effects_run
    original = ORIGINAL_MAX[_types(loops_cfg)[v]]
    _assert_capped(run, v, 60 + BRAKE, 150, 5)
    # SUMO's max speed: the cap from the step after activation to the step after deactivation, then restored.
    assert {t: m for t, m in max_speed[v].items() if 61 <= t <= 151} == {t: 5.0 for t in range(61, 152)}
    assert all(m == original for t, m in max_speed[v].items() if t <= 60 or t >= 152), max_speed[v]


def test_capped_vehicles_drive_faster_after_the_story(effects_run: tuple[StoryRun, dict]) -> None:
    run, _ = effects_run
    # Free vehicles in this grid reach 10 m/s and more within a minute.
    for v in CAP:
        _assert_moves_above(run, v, 152, 260, 6)


@pytest.mark.parametrize("v", LOW_THEN_HIGH)
def test_latest_cap_rules_and_the_earlier_comes_back(
    effects_run: tuple[StoryRun, dict], loops_cfg: Path, v: str
) -> None:
    run, max_speed = effects_run
    original = ORIGINAL_MAX[_types(loops_cfg)[v]]
    expected = {
        t: 4.0 if 61 <= t <= 100 or 152 <= t <= 201 else 9.0 if 101 <= t <= 151 else original for t in max_speed[v]
    }
    assert max_speed[v] == expected
    _assert_capped(run, v, 60 + BRAKE, 100, 4)
    _assert_capped(run, v, 100, 151, 9)
    _assert_capped(run, v, 151 + BRAKE, 201, 4)


def test_a_raised_cap_is_really_used(effects_run: tuple[StoryRun, dict]) -> None:
    run, _ = effects_run
    # At least one of them goes above the outer cap of 4 m/s while the inner cap of 9 m/s rules.
    assert any(max(_speeds(run, v, 101, 151).values()) > 4.5 for v in LOW_THEN_HIGH)


@pytest.mark.parametrize("v", HIGH_THEN_LOW)
def test_earlier_cap_ending_keeps_the_later(effects_run: tuple[StoryRun, dict], loops_cfg: Path, v: str) -> None:
    run, max_speed = effects_run
    original = ORIGINAL_MAX[_types(loops_cfg)[v]]
    expected = {t: 9.0 if 61 <= t <= 80 else 4.0 if 81 <= t <= 201 else original for t in max_speed[v]}
    assert max_speed[v] == expected
    _assert_capped(run, v, 80 + BRAKE, 201, 4)


@pytest.mark.parametrize("v", STOP_TWICE)
def test_overlapping_stops_hold_until_the_last_ends(effects_run: tuple[StoryRun, dict], v: str) -> None:
    run, _ = effects_run
    speeds = _speeds(run, v, 50 + BRAKE + 2, 151)
    moving = {t: s for t, s in speeds.items() if s > 0}
    assert not moving, f"{v} moved while a stop held it: {moving}"
    _assert_moves_above(run, v, 152, 260, 1)


def test_a_single_stop_releases_when_it_ends(effects_run: tuple[StoryRun, dict]) -> None:
    """The control for the overlapping stops: the same stop alone releases its vehicles at 101 s."""
    run, _ = effects_run
    for v in STOP_ONCE:
        assert not any(s > 0 for s in _speeds(run, v, 50 + BRAKE + 2, 101).values()), v
    assert all(max(_speeds(run, v, 102, 151).values()) > 1 for v in STOP_ONCE)


def test_emergency_stop_brakes_hard_and_restores_the_speed_mode(effects_run: tuple[StoryRun, dict]) -> None:
    run, _ = effects_run
    modes = {
        tuple(line.split()[:2]): int(line.split()[2])
        for line in run.story.with_name("modes.txt").read_text().splitlines()
    }
    for v in EMERGENCY:
        speeds = _speeds(run, v, 49, 53)
        assert speeds[50] > 5, f"{v} should be driving when the emergency stop begins: {speeds}"
        # Emergency deceleration (9 m/s^2 for SUMO's cars) instead of 4.5: standing within 2 steps.
        assert speeds[52] == 0, speeds
        # As in Artery, its own speed checks are off while the emergency stop is active, and back afterwards.
        assert modes[(v, "before")] == 31
        assert modes[(v, "after")] == modes[(v, "before")]
        _assert_moves_above(run, v, 102, 200, 1)


def test_stop_after_emergency_stop_holds_until_the_last_ends(effects_run: tuple[StoryRun, dict]) -> None:
    run, _ = effects_run
    for v in EMERGENCY_THEN_STOP:
        assert _speeds(run, v, 50, 53)[52] == 0
        speeds = _speeds(run, v, 70 + BRAKE, 151)
        assert not any(s > 0 for s in speeds.values()), speeds
        _assert_moves_above(run, v, 152, 260, 1)


def test_unaffected_vehicles_keep_their_max_speed(effects_run: tuple[StoryRun, dict], loops_cfg: Path) -> None:
    _, max_speed = effects_run
    types = _types(loops_cfg)
    for v in STOP_TWICE + STOP_ONCE + EMERGENCY + EMERGENCY_THEN_STOP:
        assert set(max_speed[v].values()) == {ORIGINAL_MAX[types[v]]}, v
