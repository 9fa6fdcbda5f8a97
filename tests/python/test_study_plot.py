"""sbsim.study --plot COLUMN: a runs.parquet column (a story's statistic) drawn against the swept parameter, its
data checked against runs.parquet and the runs' own figures."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest
from sbsim.study.tables import column_by_parameter, draw_column
from sbsim_helpers import write_story

# Each vehicle faster than the threshold records its speed at that moment: stat:fast_speed:mean lies above
# the threshold, and stat:fast_speed:count is the story's activations.
STORY = """
    import storyboard

    def createStories(board):
        class Record(storyboard.Effect):
            def apply(self, vehicle):
                board.record("fast_speed", vehicle.speed, vehicle=vehicle.id)
            def remove(self, vehicle):
                pass

        fast = storyboard.SpeedConditionGreater(float(board.parameter("threshold", 5)))
        board.registerStory(storyboard.Story(fast, [Record()], name="fast"))
"""

PYTHON_ROOT = Path(__file__).resolve().parents[2] / "python"


@pytest.fixture
def env() -> dict[str, str]:
    """Dask workers import sbsim.study: they must see this tree's python/ folder."""
    return {**os.environ, "PYTHONPATH": f"{PYTHON_ROOT}:{os.environ.get('PYTHONPATH', '')}"}


def write_study(trips_cfg: Path, folder: Path) -> Path:
    story = write_story(folder, STORY)
    toml = folder / "study.toml"
    toml.write_text(
        f'sumocfg = "{trips_cfg}"\nstory = "{story}"\nend = 40\nargs = ["--threads", "1"]\n'
        "seeds = { first = 1, count = 2 }\n[parameters]\nthreshold = [3.0, 6.0, 9.0]\n"
        f'[outputs]\ndirectory = "{folder / "results"}"\n',
        encoding="utf-8",
    )
    return toml


def test_plot_a_statistic_against_the_parameter(trips_cfg: Path, tmp_path: Path, env: dict[str, str]) -> None:
    toml = write_study(trips_cfg, tmp_path)
    command = [sys.executable, "-m", "sbsim.study", str(toml), "--workers", "2", "--plot", "stat:fast_speed:mean"]
    done = subprocess.run(command, capture_output=True, text=True, timeout=600, env=env, check=False)
    assert done.returncode == 0, done.stderr
    image = tmp_path / "results" / "plot-stat_fast_speed_mean.png"
    assert f"study: plot {image}" in done.stdout.splitlines()
    assert image.read_bytes().startswith(b"\x89PNG")

    runs = pd.read_parquet(tmp_path / "results" / "runs.parquet")
    assert len(runs) == 6 and (runs["exit_code"] == 0).all()
    # The statistic is what the runs recorded: one value per activation, each above the threshold.
    assert (runs["stat:fast_speed:count"] == runs["activations:fast"]).all()
    assert (runs["stat:fast_speed:min"] > runs["threshold"]).all()
    data = column_by_parameter(runs, "stat:fast_speed:mean", ["threshold"])
    assert data["x"].tolist() == [3.0, 6.0, 9.0] and (data["runs"] == 2).all()
    for _, row in data.iterrows():
        values = runs.loc[runs["threshold"] == row["x"], "stat:fast_speed:mean"]
        assert row["mean"] == pytest.approx(values.mean()) and row["std"] == pytest.approx(values.std())
    figure = draw_column(data, "stat:fast_speed:mean", ["threshold"])
    [ax] = figure.axes
    [bars] = ax.containers  # one errorbar per group: its data line, caps and bars
    assert bars.get_label() == "stat:fast_speed:mean"
    line = bars.lines[0]
    assert list(line.get_xdata()) == [3.0, 6.0, 9.0] and list(line.get_ydata()) == data["mean"].tolist()
    assert ax.get_xlabel() == "threshold" and ax.get_ylabel() == "stat:fast_speed:mean"

    # Bare --plot still draws the activations; an unknown column is one line and exit 2 (the runs are kept).
    again = subprocess.run(
        [*command[:-2], "--plot", "--plot", "stat:nope:mean"],
        capture_output=True,
        text=True,
        timeout=600,
        env=env,
        check=False,
    )
    assert again.returncode == 2, again.stderr
    assert (tmp_path / "results" / "activations-fast.png").exists()
    [line] = [line for line in again.stderr.splitlines() if line.strip()]
    assert (
        line.startswith("study: --plot: runs.parquet has no column 'stat:nope:mean'") and "stat:fast_speed:mean" in line
    )
