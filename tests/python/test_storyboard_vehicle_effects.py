"""Speed factor, type, colour and exit signals on generated scenarios, checked against SUMO's FCD output;
and Artery's leftover names (RNG, EffectFactory, getWarmupEndTime with --warmup)."""

from __future__ import annotations

from pathlib import Path

import pytest
from sbsim_helpers import StoryRun, active_timeline, run_story

LIMIT = 13.89  # the grid's speed limit (make_grid's default)
STEP = 1.0

EFFECTS_STORY = """
    import storyboard as sb
    def createStories(board):
        cars = sb.TypeCondition("car")
        board.registerStory(sb.Story(sb.all_of(cars, sb.TimeCondition(0, 120)), [sb.SpeedFactorEffect(0.5)], "rain"))
        board.registerStory(sb.Story(sb.all_of(cars, sb.TimeCondition(40, 80), sb.LimitCondition(10)),
                                     [sb.TypeEffect("truck"), sb.ColorEffect((255, 0, 0))], "disguise"))
        board.registerStory(sb.Story(sb.SpeedConditionLess(0.1),
                                     [sb.SignalEffect("stopped", on_exit="moving again")], "stops"))
"""


@pytest.fixture(scope="module")
def effects_run(trips_cfg: Path, tmp_path_factory: pytest.TempPathFactory) -> StoryRun:
    return run_story(trips_cfg, EFFECTS_STORY, tmp_path_factory.mktemp("effects"), end=200, fcd=True)


def test_speed_factor_slows_vehicles_while_active_and_ends(effects_run: StoryRun) -> None:
    fcd = effects_run.fcd
    assert fcd is not None
    timeline = active_timeline(effects_run.events, "rain", fcd.times)
    checked = 0
    for t in fcd.times:
        # A factor set after one step shows from the next on; a vehicle faster than the new
        # limit (one that departed fast) brakes over a few steps at its deceleration.
        earlier = [timeline.get(round(t - k * STEP, 3), frozenset()) for k in (1, 2, 3)]
        for v in earlier[0] & earlier[1] & earlier[2] & timeline[t]:
            assert fcd.speed[v][t] <= 0.5 * LIMIT + 0.01, f"{v} at {t}: {fcd.speed[v][t]} m/s under a 0.5 factor"
            checked += 1
    assert checked > 200
    # Without the factor (after 120 s) cars drive faster than half the limit again.
    after = [fcd.speed[v][t] for t in fcd.times if t > 140 for v in fcd.running[t] if fcd.type[v][t] == "car"]
    assert max(after) > 0.5 * LIMIT + 1


def test_type_effect_changes_the_type_and_restores_it(effects_run: StoryRun) -> None:
    fcd = effects_run.fcd
    assert fcd is not None
    disguised = effects_run.activated("disguise")
    assert disguised
    timeline = active_timeline(effects_run.events, "disguise", fcd.times)
    for v in disguised:
        seen = {t: fcd.type[v][t] for t in fcd.times if v in fcd.running[t]}
        for t, type_id in seen.items():
            # A command after the step at t - 1 shows in the step that ends at t.
            expected = "truck" if v in timeline.get(round(t - STEP, 3), frozenset()) else "car"
            assert type_id == expected, f"{v} at {t}: type {type_id}, expected {expected}"
        assert any(v in timeline[t] for t in seen), v


def test_exit_signals_come_with_condition_deactivations_only(effects_run: StoryRun) -> None:
    exits = [e for e in effects_run.of(type="signal", story="stops") if e.get("phase") == "exit"]
    by_condition = effects_run.of(type="deactivate", story="stops", reason="condition")
    assert len(exits) == len(by_condition) > 10
    assert all(e["cause"] == "moving again" and e["others"] == [] for e in exits)
    assert {(e["t"], e["vehicle"]) for e in exits} == {(e["t"], e["vehicle"]) for e in by_condition}
    entries = [e for e in effects_run.of(type="signal", story="stops") if "phase" not in e]
    assert len(entries) == len(effects_run.of(type="activate", story="stops"))
    # The exit line follows its deactivation line.
    for k, e in enumerate(effects_run.events):
        if e.get("phase") == "exit":
            previous = effects_run.events[k - 1]
            assert (previous["type"], previous["vehicle"]) == ("deactivate", e["vehicle"])


ARTERY_NAMES_STORY = """
    import storyboard
    def createStories(board):
        assert storyboard.RNG is storyboard.RandomNumberGenerator
        assert isinstance(board.getRandomNumberGenerator(), storyboard.RNG)
        assert isinstance(storyboard.SpeedEffect(3), storyboard.EffectFactory)
        assert storyboard.EffectFactory is storyboard.Effect
        assert float(board.getWarmupEndTime()) == WARMUP, board.getWarmupEndTime()
        assert float(board.warmup_end_time) == WARMUP
        board.registerStory(storyboard.Story(storyboard.TimeCondition(0), [], "all"))
"""


@pytest.mark.parametrize(("extra", "warmup"), [((), 0.0), (("--warmup", "30"), 30.0)])
def test_artery_names_and_warmup(trips_cfg: Path, tmp_path: Path, extra: tuple[str, ...], warmup: float) -> None:
    source = ARTERY_NAMES_STORY.replace("WARMUP", repr(warmup))
    run = run_story(trips_cfg, source, tmp_path, end=20, extra=extra)
    assert run.activated("all"), "stories run during the warm-up"
