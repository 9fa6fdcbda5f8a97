"""Conditions that ask SUMO what the snapshot lacks: the leader's headway and this step's collisions."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from sbsim_helpers import StoryRun, run_story

HEADWAY_STORY = """
    import storyboard as sb
    def createStories(board):
        board.registerStory(sb.Story(sb.HeadwayCondition(2.0), [sb.SignalEffect("close")], "headway"))
"""


@pytest.fixture(scope="module")
def headway_run(trips_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> StoryRun:
    return run_story(trips_cfg, HEADWAY_STORY, tmp_path_factory.mktemp("headway"), end=200, fcd=True)


def test_headway_yields_a_close_leader_of_a_moving_ego(headway_run: StoryRun) -> None:
    fcd = headway_run.fcd
    assert fcd is not None
    signals = headway_run.of(type="signal", story="headway")
    assert len(signals) > 10
    for s in signals:
        t, ego = float(s["t"]), s["vehicle"]
        assert len(s["others"]) == 1
        leader = s["others"][0]
        speed = fcd.speed[ego][t]
        assert speed >= 0.1, f"{ego} stands at {t} but has a headway"
        assert leader in fcd.running[t]
        # Bumper to bumper below 2 s at this speed: front bumpers at most that plus a vehicle length apart.
        assert math.dist(fcd.pos[ego][t], fcd.pos[leader][t]) < speed * 2.0 + 20, (ego, leader, t)
    # Each activation has its signal: the story is active exactly while the gap is short.
    assert len(signals) == len(headway_run.activated("headway"))


COLLISION_STORY = """
    import storyboard as sb

    class Reckless(sb.Effect):
        # No safe-speed checks at all: rear-end collisions follow.
        def apply(self, vehicle):
            vehicle.set_speed_mode(0)
            vehicle.set_speed(25)

        def remove(self, vehicle):
            pass

    def createStories(board):
        board.registerStory(sb.Story(sb.all_of(sb.TimeCondition(20), sb.LimitCondition(15)), [Reckless()], "reckless"))
        board.registerStory(sb.Story(sb.CollisionCondition(), [sb.SignalEffect("crash")], "crash"))
"""


def test_collisions_reported_by_sumo_are_detected(trips_cfg: Path, tmp_path: Path) -> None:
    collisions = tmp_path / "collisions.xml"
    run = run_story(
        trips_cfg,
        COLLISION_STORY,
        tmp_path,
        end=150,
        sumo_options=(f"--collision.action warn --collision-output {collisions}",),
    )
    # SUMO's own record: (time after the step, collider, victim).
    reported = {
        (round(float(c.attrib["time"]) + 1.0, 3), c.attrib["collider"], c.attrib["victim"])
        for c in ET.parse(collisions).getroot().iter("collision")
    }
    assert reported, "the scenario must make SUMO report collisions"
    signals = run.of(type="signal", story="crash")
    assert signals
    pairs_at = {(t, a, b) for t, a, b in reported} | {(t, b, a) for t, a, b in reported}
    for s in signals:
        for other in s["others"]:
            assert any((float(s["t"]) + d, s["vehicle"], other) in pairs_at for d in (0.0, 1.0)), s
    # Every party of a reported collision that starts one gets its signal.
    starts = {(t, a) for t, a, _ in reported} | {(t, b) for t, _, b in reported}
    signalled = {(float(s["t"]), s["vehicle"]) for s in run.of(type="activate", story="crash")}
    assert signalled, "crash story never activated"
    assert len(signalled) <= len(starts)
