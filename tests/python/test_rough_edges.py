"""Rough edges a new user hit (issue 23): two stories with one name, an exception from a service,
a middleware interval shorter than SUMO's step, a signal for a vehicle without services."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from sbsim.runner import RunResult, run
from sbsim_helpers import assert_no_crash, run_story, write_story


def services_file(directory: Path, body: str) -> Path:
    path = directory / "services.xml"
    path.write_text(f'<?xml version="1.0" encoding="UTF-8"?>\n<services>\n{body}\n</services>\n', encoding="utf-8")
    return path


def run_services(cfg: Path, module: Path, services: Path, *extra: str, story: Path | None = None) -> RunResult:
    result = run(
        cfg, story=story, end=30.0, extra=["--plugin", str(module), "--services", str(services), *extra], timeout=120
    )
    assert_no_crash(result)
    return result


def test_two_stories_with_one_name_are_an_error(loops_cfg: Path, tmp_path: Path) -> None:
    story = write_story(
        tmp_path,
        """
        from storyboard import SpeedEffect, Story, TimeCondition

        def createStories(board):
            board.registerStory(Story(TimeCondition(10), [SpeedEffect(5)], name="rain"))
            board.registerStory(Story(TimeCondition(20), [SpeedEffect(3)], name="rain"))  # the second
        """,
    )
    result = run(loops_cfg, story=story, end=30.0, timeout=120)
    assert_no_crash(result)
    assert result.returncode == 2, result.stderr
    last = result.stderr.strip().splitlines()[-1]
    assert "two stories are named 'rain'" in result.stderr and str(story) in last, result.stderr
    assert result.stdout == ""  # the run never started


def test_a_default_name_taken_by_a_given_one_is_an_error_too(loops_cfg: Path, tmp_path: Path) -> None:
    story = write_story(
        tmp_path,
        """
        from storyboard import SpeedEffect, Story, TimeCondition

        def createStories(board):
            board.registerStory(Story(TimeCondition(10), [SpeedEffect(5)], name="story1"))
            board.registerStory(Story(TimeCondition(20), [SpeedEffect(3)]))  # story1 by default
        """,
    )
    result = run(loops_cfg, story=story, end=30.0, timeout=120)
    assert result.returncode == 2 and "two stories are named 'story1'" in result.stderr, result.stderr


def test_an_exception_from_a_service_names_it(loops_cfg: Path, services_module: Path, tmp_path: Path) -> None:
    services = services_file(
        tmp_path, '<service type="ThrowingService" after="3"><filters><name pattern="veh07"/></filters></service>'
    )
    result = run_services(loops_cfg, services_module, services)
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert re.fullmatch(
        r"sbsim: service ThrowingService on vehicle veh07 at t=\d+(\.\d+)? s: the service's own bug", lines[0]
    ), lines[0]


def test_a_middleware_interval_shorter_than_the_step_warns(
    loops_cfg: Path, services_module: Path, tmp_path: Path
) -> None:
    services = services_file(tmp_path, '<service type="SpeedStatisticsService"/>')
    warning = "--middleware-interval 0.5 s is shorter than SUMO's step length (1 s)"
    short = run_services(loops_cfg, services_module, services, "--middleware-interval", "0.5")
    assert short.returncode == 0 and warning in short.stderr, short.stderr
    as_param = run_services(loops_cfg, services_module, services, "--param", "middleware_interval=0.5")
    assert as_param.returncode == 0 and warning in as_param.stderr, as_param.stderr
    for extra in (("--middleware-interval", "1"), ()):  # the step itself; the default stays quiet
        quiet = run_services(loops_cfg, services_module, services, *extra)
        assert quiet.returncode == 0 and "middleware-interval" not in quiet.stderr, quiet.stderr


def test_a_signal_for_a_vehicle_without_services_is_counted_and_warned_once(
    loops_cfg: Path, services_module: Path, tmp_path: Path
) -> None:
    services = services_file(
        tmp_path, '<service type="SpeedStatisticsService"><filters><name pattern="veh01"/></filters></service>'
    )
    story = write_story(
        tmp_path,
        """
        from storyboard import AndCondition, CarSetCondition, SignalEffect, Story, TimeCondition

        def createStories(board):
            # veh01 has services, veh02 and veh03 have none: two signals each (on entry and on exit).
            who = CarSetCondition(["veh01", "veh02", "veh03"])
            board.registerStory(Story(AndCondition(TimeCondition(5, 10), who), [SignalEffect("ice", on_exit="thaw")],
                                      name="ice"))
        """,
    )
    result = run_services(loops_cfg, services_module, services, story=story)
    assert result.returncode == 0, result.stderr
    warnings = [line for line in result.stderr.splitlines() if "which has no services" in line]
    assert len(warnings) == 1, result.stderr
    assert "story 'ice'" in warnings[0] and "vehicle veh02" in warnings[0], warnings[0]
    assert "signals without services: 4" in result.stdout.splitlines(), result.stdout


GRADUAL = """
from storyboard import AndCondition, CarSetCondition, SpeedEffect, Story, TimeCondition

def createStories(board):
    # From t = 60 s (the loop traffic runs at ~13 m/s), down to 2 m/s: at once, or over 10 s.
    board.registerStory(Story(AndCondition(TimeCondition(60), CarSetCondition(["veh05", "veh06", "veh07"])),
                              [SpeedEffect(2.0{over})], name="rain"))
"""


def test_a_gradual_speed_effect_ramps_down_by_slow_down(loops_cfg: Path, tmp_path: Path) -> None:
    runs = {}
    for label, over in (("plain", ""), ("gradual", ", over=10")):
        runs[label] = run_story(loops_cfg, GRADUAL.format(over=over), tmp_path / label, end=90.0, seed=1, fcd=True)
    for vehicle in ("veh05", "veh06", "veh07"):
        before = runs["gradual"].fcd.speeds(vehicle, 60, 60)[60.0]
        assert before > 8.0, before  # driving when the story starts
        gradual = runs["gradual"].fcd.speeds(vehicle, 60, 90)
        plain = runs["plain"].fcd.speeds(vehicle, 60, 90)
        # At once: down to the cap within the next steps, braking as hard as it must.
        assert plain[62.0] <= 2.0 + 1e-6, plain
        # Gradually: by SUMO's linear slowDown, (before - 2) / 10 per second (the traffic ahead may
        # ask for more later on: a junction, a leader), then capped.
        for t in (61.0, 62.0):
            expected = before - (before - 2.0) * (t - 60.0) / 10.0
            assert gradual[t] == pytest.approx(expected, abs=0.3), (vehicle, t, gradual)
            assert gradual[t] > plain[t] + 2.0, (vehicle, t, gradual, plain)
        assert max(v for t, v in gradual.items() if t >= 72.0) <= 2.0 + 1e-6, gradual
    # A cap far below the speed makes SUMO warn of emergency braking; the ramp does not.
    assert "emergency braking" not in runs["gradual"].result.stderr + runs["gradual"].result.stdout


def test_a_speed_effect_over_negative_seconds_is_an_error(loops_cfg: Path, tmp_path: Path) -> None:
    result = run_story(loops_cfg, GRADUAL.format(over=", over=-1"), tmp_path, end=5.0, check=False).result
    assert result.returncode == 2 and "over" in result.stderr, result.stderr
