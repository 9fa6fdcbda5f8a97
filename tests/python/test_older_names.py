"""The host tools' older names (storyboard.runner, storyboard.report, storyboard.study) still work:
the same objects as sbsim's, and the same commands."""

from __future__ import annotations

import importlib
import os
import subprocess
import sys
from pathlib import Path

import pytest
from sbsim.runner import run
from sbsim_helpers import REPO, write_story

STORY = """
    import storyboard

    def createStories(board):
        fast = storyboard.SpeedConditionGreater(8.0)
        board.registerStory(storyboard.Story(fast, [storyboard.SignalEffect("fast")], name="fast"))
"""


def module(name: str, *args: str | Path) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(REPO / "python"), os.environ.get("PYTHONPATH", "")])}
    return subprocess.run(
        [sys.executable, "-m", name, *map(str, args)], capture_output=True, text=True, env=env, timeout=300, check=False
    )


@pytest.mark.parametrize("name", ["runner", "report", "study"])
def test_the_older_module_is_the_new_ones_api(name: str) -> None:
    new, old = importlib.import_module(f"sbsim.{name}"), importlib.import_module(f"storyboard.{name}")
    assert new.__all__ and all(getattr(old, attribute) is getattr(new, attribute) for attribute in new.__all__)


def test_both_report_commands_write_the_same_page(trips_cfg: Path, tmp_path: Path) -> None:
    events = tmp_path / "events.jsonl"
    result = run(trips_cfg, story=write_story(tmp_path, STORY), events=events, end=40, quiet=True)
    assert result.returncode == 0, result.stderr
    pages = {}
    for name in ("sbsim.report", "storyboard.report"):
        page = tmp_path / f"{name}.html"
        done = module(name, events, "--sumocfg", trips_cfg, "-o", page)
        assert (done.returncode, done.stderr) == (0, ""), done.stderr
        pages[name] = page.read_bytes()
    assert b"fast" in pages["sbsim.report"] and pages["sbsim.report"] == pages["storyboard.report"]


def test_both_study_commands_say_the_same_about_a_bad_file(tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text('sumocfg = "x.sumocfg"\nseeds = []\n', encoding="utf-8")
    new, old = module("sbsim.study", bad), module("storyboard.study", bad)
    assert new.returncode == old.returncode == 2
    assert new.stderr == old.stderr and new.stderr.startswith("study: ") and new.stderr.count("\n") == 1


def test_both_runner_commands_print_the_cmake_prefix() -> None:
    new, old = module("sbsim.runner", "--cmake-prefix"), module("storyboard.runner", "--cmake-prefix")
    assert new.returncode == old.returncode == 0
    assert new.stdout == old.stdout and new.stdout.strip().endswith("sbsim")
