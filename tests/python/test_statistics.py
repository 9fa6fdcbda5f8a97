"""Statistics: a service module records a time series (emit) and scalars (recordScalar), a story
records with board.record; the --statistics Parquet file and the summary's aggregates agree."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import pandas as pd
import pytest
from sbsim.runner import executable, run
from sbsim.summary import table_columns
from sbsim_helpers import SERVICES_SOURCE, assert_no_crash, write_story

STORY = """
from storyboard import CarSetCondition, Effect, Story, TimeCondition, AndCondition

class Mark(Effect):
    def __init__(self, board):
        super().__init__()
        self.board = board

    def apply(self, vehicle):
        self.board.record("story_marks", 2.5, vehicle=vehicle.id, story="marker")

    def remove(self, vehicle):
        pass

def createStories(board):
    when = AndCondition(TimeCondition(20, 40), CarSetCondition(["veh01", "veh02"]))
    board.registerStory(Story(when, [Mark(board)], name="marker"))
"""


def test_service_and_story_statistics_agree_with_the_summary(
    services_module: Path, loops_cfg: Path, tmp_path: Path
) -> None:
    story = write_story(tmp_path, STORY)
    parquet = tmp_path / "stats.parquet"
    summary_path = tmp_path / "summary.json"
    extra = ["--plugin", str(services_module), "--services", str(SERVICES_SOURCE / "services.xml")]
    extra += ["--statistics", str(parquet), "--summary", str(summary_path)]
    result = run(loops_cfg, story=story, end=60.0, seed=4, extra=extra, timeout=180)
    assert_no_crash(result)
    assert result.returncode == 0, result.stderr
    table = pd.read_parquet(parquet)
    assert list(table.columns) == ["vehicle", "source", "name", "time", "value", "equipped"]
    assert set(table["name"]) == {"speed", "triggers", "top_speed", "story_marks"}
    services = table[table["source"] == "SpeedStatisticsService"]
    # 30 vehicles, each with its one series and two scalars at the end.
    assert services["vehicle"].nunique() == 30
    speed = services[services["name"] == "speed"]
    # One value per trigger: a vehicle's count of speed rows is its "triggers" scalar.
    triggers = services[services["name"] == "triggers"].set_index("vehicle")["value"]
    assert (speed.groupby("vehicle").size() == triggers.astype(int)).all()
    # The series is on each vehicle's own 0.1 s clock: one offset within the period per vehicle.
    offsets = ((speed["time"] * 1e9).round().astype("int64") % 100_000_000).groupby(speed["vehicle"]).nunique()
    assert (offsets == 1).all()
    tops = services[services["name"] == "top_speed"].set_index("vehicle")["value"]
    assert (speed.groupby("vehicle")["value"].max() == tops).all()
    assert speed["value"].max() > 5.0  # vehicles do move
    assert services["equipped"].all()  # the default penetration, 1: every vehicle is equipped
    marks = table[table["name"] == "story_marks"]
    assert (marks["source"] == "marker").all() and (marks["value"] == 2.5).all()
    assert marks["time"].between(20, 40).all() and len(marks) > 0
    # The summary's aggregates are the file's.
    summary = json.loads(summary_path.read_text(encoding="utf-8"))
    for name, rows in table.groupby("name"):
        aggregate = summary["statistics"][name]
        assert aggregate["count"] == len(rows)
        assert aggregate["sum"] == pytest.approx(rows["value"].sum())
        assert aggregate["mean"] == pytest.approx(rows["value"].mean())
        assert aggregate["min"] == rows["value"].min()
        assert aggregate["max"] == rows["value"].max()
    row = table_columns(summary)  # a study's row
    assert row["stat:speed:count"] == len(speed) and row["stat:story_marks:max"] == 2.5
    line = f"statistic story_marks: count {len(marks)}, mean 2.5, min 2.5, max 2.5, sum {2.5 * len(marks):g}"
    assert line in result.stdout.splitlines(), result.stdout


def test_missing_pyarrow_is_one_line_before_the_run(loops_cfg: Path, tmp_path: Path) -> None:
    # A pyarrow that cannot be imported, first on the embedded Python's path.
    fake = tmp_path / "site" / "pyarrow"
    fake.mkdir(parents=True)
    (fake / "__init__.py").write_text("raise ImportError('pyarrow is broken here')\n", encoding="utf-8")
    env = {**os.environ, "PYTHONPATH": str(tmp_path / "site")}
    out = tmp_path / "stats.parquet"
    args = [str(executable()), "--sumocfg", str(loops_cfg), "--statistics", str(out), "--end", "5"]
    done = subprocess.run(args, capture_output=True, text=True, env=env, timeout=120, check=False)
    assert done.returncode == 2, done.stderr
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and "--statistics" in lines[0] and "pyarrow" in lines[0], done.stderr
    # The exact command to run (issue 29), for the interpreter sbsim embeds.
    assert "(install it with: " in lines[0] and " -m pip install 'pyarrow>=14')" in lines[0], lines[0]
    assert done.stdout == ""  # no summary: the run never started
    assert not out.exists()


def test_board_record_refuses_a_value_that_is_not_finite(loops_cfg: Path, tmp_path: Path) -> None:
    story = write_story(
        tmp_path,
        """
        def createStories(board):
            board.record("bad", float("nan"))
        """,
    )
    result = run(loops_cfg, story=story, end=5.0, timeout=120)
    assert_no_crash(result)
    assert result.returncode == 2, result.stderr
    assert "board.record" in result.stderr and "not finite" in result.stderr, result.stderr
