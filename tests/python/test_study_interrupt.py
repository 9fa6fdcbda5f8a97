"""A study stopped by SIGINT (Ctrl-C, or ``kill -INT``) or SIGTERM: its runs under way are stopped (only
``*.incomplete`` left, no sbsim process left running), exit code 130 with one line, no traceback; started
again it does only the runs that did not finish."""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pandas as pd
import psutil
import pytest
from sbsim_helpers import REPO, wait_until, write_story

# Slow on purpose (at least 50 ms a step whatever the machine, 120 steps): a run is surely under way
# when the signal comes. Each run touches a marker (under MARKERS, named by its process id) once it is
# stepping: the test's cue, never a fixed wait.
SLOW = """
    import os
    import time
    from pathlib import Path
    import storyboard

    class Slow(storyboard.Condition):
        columns = ("speed",)

        def test_all(self, snapshot):
            Path(MARKERS, str(os.getpid())).touch()
            time.sleep(SLEEP)
            return snapshot.speeds < 0

    def createStories(board):
        board.registerStory(storyboard.Story(Slow(), [storyboard.SignalEffect("x")], name="slow"))
"""

SEEDS = 4


def make_study(folder: Path, cfg: Path, sleep: float = 0.05) -> Path:
    for f in cfg.parent.iterdir():
        if f.is_file():
            shutil.copy(f, folder / f.name)
    (folder / "markers").mkdir()
    write_story(folder, SLOW.replace("MARKERS", repr(str(folder / "markers"))).replace("SLEEP", repr(sleep)))
    toml = folder / "study.toml"
    toml.write_text(
        f'sumocfg = "{cfg.name}"\nstory = "story.py"\nseeds = {{ first = 1, count = {SEEDS} }}\nend = 120\n'
        'args = ["--threads", "1"]\n',
        encoding="utf-8",
    )
    return toml


def start(folder: Path, how: str) -> subprocess.Popen[bytes]:
    """The study, in its own process group if a terminal's Ctrl-C is to reach the group; with SIGINT
    ignored as a script's background job (``study &``) starts it: the study must stop all the same."""
    ignore = how.endswith("(SIGINT ignored)")
    return subprocess.Popen(
        [sys.executable, "-m", "sbsim.study", "study.toml", "--workers", "2"],
        cwd=folder,
        stdin=subprocess.DEVNULL,
        stdout=open(folder / "stdout.txt", "wb"),  # noqa: SIM115 -- closed with the process
        stderr=open(folder / "stderr.txt", "wb"),  # noqa: SIM115
        env={**os.environ, "PYTHONPATH": str(REPO / "python")},
        start_new_session=how == "Ctrl-C",
        preexec_fn=(lambda: signal.signal(signal.SIGINT, signal.SIG_IGN)) if ignore else None,  # noqa: PLW1509
    )


def sbsim_processes(folder: Path) -> list[psutil.Process]:
    """Every running sbsim process working on this study (children or orphans alike)."""
    found = []
    for proc in psutil.process_iter(["cmdline", "status"]):
        cmdline = proc.info["cmdline"] or []
        if proc.info["status"] == psutil.STATUS_ZOMBIE or not cmdline:
            continue
        if Path(cmdline[0]).name == "sbsim" and any(str(folder) in word for word in cmdline):
            found.append(proc)
    return found


def still_running(proc: psutil.Process) -> bool:
    try:
        return proc.is_running() and proc.status() != psutil.STATUS_ZOMBIE
    except psutil.NoSuchProcess:
        return False


def wait_for_runs_under_way(folder: Path, study: subprocess.Popen[bytes]) -> None:
    """Returns once a run's sbsim process is stepping (its story touched its marker)."""

    def stepping() -> bool:
        markers = {m.name for m in (folder / "markers").iterdir()}
        return any(str(p.pid) in markers for p in sbsim_processes(folder))

    wait_until(stepping, "a run was stepping", study, timeout=120)


@pytest.mark.parametrize("how", ["kill -INT", "kill -INT (SIGINT ignored)", "Ctrl-C", "kill -TERM"])
def test_a_stopped_study_stops_its_runs_and_resumes(how: str, trips_cfg: Path, tmp_path: Path) -> None:
    make_study(tmp_path, trips_cfg)
    study = start(tmp_path, how)
    wait_for_runs_under_way(tmp_path, study)
    running = sbsim_processes(tmp_path)
    assert running
    if how == "Ctrl-C":  # a terminal sends it to the whole process group: workers and sbsim processes too
        os.killpg(study.pid, signal.SIGINT)
    else:
        study.send_signal(signal.SIGTERM if how == "kill -TERM" else signal.SIGINT)
    started = time.monotonic()
    assert study.wait(timeout=60) == 130
    took = time.monotonic() - started
    stderr = (tmp_path / "stderr.txt").read_text(encoding="utf-8", errors="replace")
    assert "Traceback" not in stderr and "KeyboardInterrupt" not in stderr, stderr
    last = stderr.replace("\r", "\n").strip().splitlines()[-1]
    found = re.fullmatch(
        rf"study: interrupted: (\d) of {SEEDS} runs finished and kept in (.*); "
        rf"run the same command again to do the other (\d)",
        last,
    )
    assert found, stderr
    finished = int(found[1])
    assert found[2] == str(tmp_path / "results") and finished + int(found[3]) == SEEDS
    assert finished < SEEDS  # each run takes over 10 s: the signal came before the end
    assert took < 20, took  # the runs were stopped, not waited for
    # No sbsim process is left running: neither those seen nor any other of this study. The study
    # waited for them; an orphan still going is given a grace time to end, then it is a failure.
    wait_until(
        lambda: not any(map(still_running, running)) and not sbsim_processes(tmp_path), "every sbsim ended", None, 10
    )
    # A finished run has its record; one stopped half-way left only *.incomplete outputs and no record.
    folders = sorted((tmp_path / "results" / "runs").iterdir())
    complete = [f for f in folders if (f / "result.json").exists()]
    assert len(complete) == finished
    stopped = [f for f in folders if f not in complete]
    assert stopped  # the runs that were under way
    for f in stopped:
        assert not (f / "events.jsonl").exists() and not (f / "summary.json").exists(), sorted(f.iterdir())
        assert (f / "events.jsonl.incomplete").exists()
    kept = {f.name: (f / "result.json").stat().st_mtime_ns for f in complete}
    if how != "kill -INT":
        return

    # Started again: only the missing runs, the stale *.incomplete gone, every table complete.
    again = subprocess.run(
        [sys.executable, "-m", "sbsim.study", "study.toml", "--workers", "2"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=300,
        env={**os.environ, "PYTHONPATH": str(REPO / "python")},
    )
    assert again.returncode == 0, again.stderr
    assert f"study: {SEEDS} runs ({SEEDS - finished} run now, 0 failed)" in again.stdout, again.stdout
    assert {name: (tmp_path / "results" / "runs" / name / "result.json").stat().st_mtime_ns for name in kept} == kept
    assert not list((tmp_path / "results" / "runs").glob("*/*.incomplete"))
    runs = pd.read_parquet(tmp_path / "results" / "runs.parquet")
    assert list(runs["run"]) == [f"seed-{s}" for s in range(1, SEEDS + 1)] and (runs["steps"] == 120).all()


def test_a_run_past_its_timeout_is_stopped_and_recorded_as_failed(trips_cfg: Path, tmp_path: Path) -> None:
    # The run lasts at least 60 s (0.5 s a step) whatever the machine, far past the 4 s timeout, which
    # leaves a slow machine time to start sbsim (its handlers installed) before the SIGTERM.
    make_study(tmp_path, trips_cfg, sleep=0.5)
    (tmp_path / "study.toml").write_text(
        f'sumocfg = "{trips_cfg.name}"\nstory = "story.py"\nseeds = [1]\nend = 120\n', encoding="utf-8"
    )
    done = subprocess.run(
        [sys.executable, "-m", "sbsim.study", "study.toml", "--workers", "1", "--timeout", "4"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, "PYTHONPATH": str(REPO / "python")},
    )
    assert done.returncode == 1, done.stderr
    assert "Traceback" not in done.stderr
    assert done.stderr.strip().splitlines()[-1] == "study: run seed-1 failed with exit code -1"
    run_dir = tmp_path / "results" / "runs" / "seed-1"
    # SIGTERM: sbsim stopped at its next safe point, leaving its outputs incomplete.
    assert sorted(p.name for p in run_dir.iterdir()) == [
        "events.jsonl.incomplete",
        "result.json",
        "stderr.txt",
        "summary.json.incomplete",
    ]
    assert (run_dir / "stderr.txt").read_text(encoding="utf-8").endswith("study: the run took longer than 4.0 s\n")
    runs = pd.read_parquet(tmp_path / "results" / "runs.parquet")
    assert list(runs["exit_code"]) == [-1] and "took longer" in runs["stderr_tail"][0]
    assert not sbsim_processes(tmp_path)
