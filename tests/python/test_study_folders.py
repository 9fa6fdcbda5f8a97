"""A study's runs keep what they write: {run_dir}, each run working in its own folder, relative paths
(args, plugins) against the study file's folder, runs named by seed when there are no parameters."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pandas as pd
from sbsim import study
from sbsim_helpers import REPO, SERVICES_SOURCE, write_story

STORY = """
    import pathlib
    import storyboard

    def createStories(board):
        pathlib.Path("cwd.txt").write_text(str(pathlib.Path.cwd()))
        note = board.parameter("note", None)
        if note is not None:
            pathlib.Path(note).write_text("written by the story")
        board.registerStory(storyboard.Story(storyboard.TimeCondition(1), [storyboard.SignalEffect("x")], name="t"))
"""


def run_study(toml: Path, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "sbsim.study", str(toml), "--workers", "2"],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=300,
        env={**os.environ, "PYTHONPATH": str(REPO / "python")},
    )


def scenario(folder: Path, cfg: Path) -> None:
    """The generated grid, a story and the test plugin's services file, in the study's folder."""
    folder.mkdir(parents=True)
    for f in cfg.parent.iterdir():
        if f.is_file():
            shutil.copy(f, folder / f.name)
    write_story(folder, STORY)
    shutil.copy(SERVICES_SOURCE / "services.xml", folder / "services.xml")
    (folder / "extra.add.xml").write_text("<additional/>\n", encoding="utf-8")


def test_runs_write_into_their_own_folders_with_paths_relative_to_the_study_file(
    trips_cfg: Path, services_module: Path, tmp_path: Path
) -> None:
    folder = tmp_path / "study"
    scenario(folder, trips_cfg)
    (folder / "lib").mkdir()
    shutil.copy(services_module, folder / "lib" / services_module.name)
    (folder / "study.toml").write_text(
        f"""
sumocfg = "{trips_cfg.name}"
story = "story.py"
services = "services.xml"
plugins = ["lib/{services_module.name}"]
seeds = [1, 2]
end = 30
args = ["--threads", "1", "--sumo-log", "sumo.log", "--",
        "--fcd-output", "{{run_dir}}/fcd.xml", "--additional-files", "extra.add.xml"]
[outputs]
directory = "results"
statistics = true
""",
        encoding="utf-8",
    )
    elsewhere = tmp_path / "elsewhere"  # the study is started from another folder: nothing depends on it
    elsewhere.mkdir()
    done = run_study(folder / "study.toml", elsewhere)
    assert done.returncode == 0, done.stderr
    runs_folder = folder / "results" / "runs"
    # No parameters: the runs are named by their seeds.
    assert sorted(p.name for p in runs_folder.iterdir()) == ["seed-1", "seed-2"]
    for seed in (1, 2):
        run_dir = runs_folder / f"seed-{seed}"
        # {run_dir} filled in: SUMO's FCD output of this run, in its folder, complete.
        fcd = (run_dir / "fcd.xml").read_text(encoding="utf-8")
        assert fcd.count("<timestep ") == 30 and fcd.rstrip().endswith("</fcd-export>")
        # The run works in its folder: the story's relative file and a relative output land there.
        assert (run_dir / "cwd.txt").read_text(encoding="utf-8") == str(run_dir)
        assert (run_dir / "sumo.log").is_file()
        # An existing file in args is taken relative to the study file, as an absolute path.
        command = json.loads((run_dir / "summary.json").read_text(encoding="utf-8"))["command"]
        assert command[command.index("--additional-files") + 1] == str(folder / "extra.add.xml")
        assert command[command.index("--plugin") + 1] == str(folder / "lib" / services_module.name)
    assert not list(elsewhere.iterdir())
    # The relative plugin was loaded: its service recorded statistics in every run.
    runs = pd.read_parquet(folder / "results" / "runs.parquet")
    assert list(runs["run"]) == ["seed-1", "seed-2"]
    assert (runs["stat:speed:count"] > 0).all() and (runs["exit_code"] == 0).all()
    # statistics = true: each run keeps its --statistics file; statistics.parquet holds them all, by run.
    for seed in (1, 2):
        assert (runs_folder / f"seed-{seed}" / "statistics.parquet").is_file()
    stats = pd.read_parquet(folder / "results" / "statistics.parquet")
    speed = stats[stats["name"] == "speed"].groupby("run").size()
    assert speed.to_dict() == dict(zip(runs["run"], runs["stat:speed:count"], strict=True))
    assert set(stats["seed"]) == {1, 2}


def test_run_dir_in_a_parameter_value(trips_cfg: Path, tmp_path: Path) -> None:
    folder = tmp_path / "study"
    scenario(folder, trips_cfg)
    spec = study.StudySpec.from_dict(
        {
            "sumocfg": trips_cfg.name,
            "story": "story.py",
            "seeds": [3],
            "end": 5,
            "parameters": {"note": ["{run_dir}/a.txt", "{run_dir}/b.txt", "{{literal}}.txt"]},
            "outputs": {"directory": "results"},
        },
        base=folder,
    )
    result = study.run(spec, workers=2, progress=False)
    assert not result.failed, result.failed
    runs = pd.read_parquet(spec.directory / "runs.parquet")
    # The table keeps the value as written (it names the parameter value, not the folder).
    assert list(runs["note"]) == ["{run_dir}/a.txt", "{run_dir}/b.txt", "{{literal}}.txt"]
    for r, name in zip(spec.runs(), ["a.txt", "b.txt", "{literal}.txt"], strict=True):
        run_dir = spec.directory / "runs" / r.id
        expected = name if name.startswith("{") else str(run_dir / name)
        assert r.arguments(run_dir)[-1] == f"note={expected}"
        # Each run wrote its file where the filled-in value said: its own folder (a relative one: cwd).
        assert (run_dir / name).read_text(encoding="utf-8") == "written by the story"


def test_relative_words_in_args(tmp_path: Path) -> None:
    (tmp_path / "in.xml").write_text("<additional/>\n", encoding="utf-8")
    (tmp_path / "x.sumocfg").write_text("<configuration/>\n", encoding="utf-8")
    spec = study.StudySpec.from_dict(
        {"sumocfg": "x.sumocfg", "args": ["--", "-a", "in.xml", "--route-files=in.xml", "out.xml", "-", "--x=", 7]},
        base=tmp_path,
    )
    absolute = str(tmp_path.resolve() / "in.xml")
    assert spec.args == ("--", "-a", absolute, f"--route-files={absolute}", "out.xml", "-", "--x=", "7")
