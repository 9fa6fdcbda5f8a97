"""The study runner's hostile-input corpus (tests/corpus-study/): every bad study file is one line on
stderr and exit code 2 before any run starts (no results folder, no traceback).

Each case is ``<name>.toml`` whose first line is ``# message: <regular expression>``; it is run
next to a copy of the small generated grid (grid.sumocfg). ``--timeout`` cases live below.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from sbsim_helpers import REPO

CORPUS = REPO / "tests" / "corpus-study"
CASES = sorted(p.stem for p in CORPUS.glob("*.toml"))


def run_study(folder: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "sbsim.study", *args],
        cwd=folder,
        capture_output=True,
        text=True,
        timeout=60,
        env={**os.environ, "PYTHONPATH": str(REPO / "python")},
    )


def check_refused(proc: subprocess.CompletedProcess[str], pattern: str, folder: Path) -> None:
    assert proc.returncode == 2, f"exit {proc.returncode}:\n{proc.stderr}"
    assert "Traceback" not in proc.stderr, proc.stderr
    lines = [line for line in proc.stderr.splitlines() if line.strip()]
    assert len(lines) == 1, f"expected one line:\n{proc.stderr}"
    assert re.search(pattern, lines[0]), f"{lines[0]!r} does not match {pattern!r}"
    assert not (folder / "results").exists(), "a run started"


@pytest.mark.parametrize("name", CASES)
def test_study_corpus_case(name: str, tmp_path: Path, trips_cfg: Path) -> None:
    source = CORPUS / f"{name}.toml"
    first = source.read_text(encoding="utf-8").splitlines()[0]
    assert first.startswith("# message: "), f"{source} lacks its '# message:' line"
    for f in trips_cfg.parent.iterdir():
        if f.is_file():
            shutil.copy(f, tmp_path / f.name)
    shutil.copy(source, tmp_path / "study.toml")
    check_refused(run_study(tmp_path, "study.toml"), first.removeprefix("# message: "), tmp_path)


@pytest.mark.parametrize("timeout", ["-1", "0", "nan"])
def test_study_timeout_not_positive(timeout: str, tmp_path: Path, trips_cfg: Path) -> None:
    shutil.copy(trips_cfg, tmp_path / "grid.sumocfg")
    (tmp_path / "study.toml").write_text('sumocfg = "grid.sumocfg"\n', encoding="utf-8")
    check_refused(run_study(tmp_path, "study.toml", "--timeout", timeout), r"--timeout must be > 0", tmp_path)


@pytest.mark.parametrize("address", ["not an address", "tcp://", "http://x/y", "host"])
def test_study_scheduler_malformed(address: str, tmp_path: Path, trips_cfg: Path) -> None:
    shutil.copy(trips_cfg, tmp_path / "grid.sumocfg")
    (tmp_path / "study.toml").write_text('sumocfg = "grid.sumocfg"\n', encoding="utf-8")
    check_refused(
        run_study(tmp_path, "study.toml", "--scheduler", address), r"--scheduler .* is not an address", tmp_path
    )


def test_study_output_folder_cannot_be_made(tmp_path: Path, trips_cfg: Path) -> None:
    shutil.copy(trips_cfg, tmp_path / "grid.sumocfg")
    (tmp_path / "blocker").write_text("a file where the folder's parent should be", encoding="utf-8")
    (tmp_path / "study.toml").write_text(
        'sumocfg = "grid.sumocfg"\n[outputs]\ndirectory = "blocker/results"\n', encoding="utf-8"
    )
    check_refused(run_study(tmp_path, "study.toml"), r"output folder .* cannot be made", tmp_path)
