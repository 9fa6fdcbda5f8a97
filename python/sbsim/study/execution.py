"""Running a study: one ``sbsim`` process per run, started by a Dask task, each in its own folder."""

from __future__ import annotations

import json
import os
import subprocess
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from sbsim.runner import executable
from sbsim.study.spec import Run, StudySpec
from sbsim.study.tables import COMPLETE, write_tables
from sbsim.summary import read_summary, table_columns

#: How much of a failed run's stderr its row keeps.
STDERR_TAIL = 2000


def result_of(folder: Path) -> dict[str, Any] | None:
    """A finished run's row, or None if it has none (not run, or stopped half-way)."""
    try:
        return json.loads((folder / "result.json").read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError):
        return None


def execute(spec: StudySpec, run: Run, program: str, timeout: float | None = None) -> dict[str, Any]:
    """Runs one sbsim process (on a Dask worker) and returns its row; never raises for a failed run."""
    folder = spec.directory / "runs" / run.id
    folder.mkdir(parents=True, exist_ok=True)
    started = time.monotonic()
    try:
        proc = subprocess.run(
            spec.command(run, folder, program),
            capture_output=True,
            text=True,
            timeout=timeout,
            stdin=subprocess.DEVNULL,
        )
        code, stderr = proc.returncode, proc.stderr
    except subprocess.TimeoutExpired:
        code, stderr = -1, f"study: the run took longer than {timeout} s"
    wall = time.monotonic() - started
    (folder / "stderr.txt").write_text(stderr, encoding="utf-8")
    row: dict[str, Any] = {"run": run.id, **dict(run.parameters), "seed": run.seed, "exit_code": code}
    row["wall_s"] = round(wall, 3)
    row["stderr_tail"] = stderr[-STDERR_TAIL:] if code not in COMPLETE else ""
    summary = folder / "summary.json"
    if code in COMPLETE and summary.exists():
        row.update(table_columns(read_summary(summary)))
    # Written last, through a rename: its presence says the run is finished.
    tmp = folder / "result.json.tmp"
    tmp.write_text(json.dumps(row), encoding="utf-8")
    tmp.replace(folder / "result.json")
    return row


@dataclass
class StudyResult:
    directory: Path
    rows: list[dict[str, Any]]
    ran: int  # runs executed now (the others were complete already)

    @property
    def failed(self) -> list[dict[str, Any]]:
        return [r for r in self.rows if r["exit_code"] not in COMPLETE]


@contextmanager
def _cluster(scheduler: str | None, workers: int | None) -> Iterator[Any]:
    from distributed import Client, LocalCluster

    if scheduler:
        with Client(scheduler) as client:
            yield client
        return
    n = workers or os.cpu_count() or 1
    with (
        LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster,
        Client(cluster) as client,
    ):
        yield client


def run(
    spec: StudySpec,
    *,
    scheduler: str | None = None,
    workers: int | None = None,
    progress: bool = True,
    timeout: float | None = None,
) -> StudyResult:
    """Runs the study's missing runs on Dask, then writes runs.parquet and events.parquet."""
    from distributed import as_completed

    program = str(executable().resolve())
    runs = spec.runs()
    rows: dict[str, dict[str, Any]] = {}
    todo = []
    for r in runs:
        done = result_of(spec.directory / "runs" / r.id)
        if done is not None and done.get("exit_code") in COMPLETE:
            rows[r.id] = done
        else:
            todo.append(r)
    if todo:
        with _cluster(scheduler, workers) as client:
            if progress and client.dashboard_link:
                print(f"study: {len(todo)} of {len(runs)} runs to do; dashboard {client.dashboard_link}", flush=True)
            futures = [client.submit(execute, spec, r, program, timeout, key=f"sbsim-{r.id}", pure=False) for r in todo]
            bar = _progress(len(futures), enabled=progress)
            try:
                for future in as_completed(futures):
                    row = future.result()
                    rows[row["run"]] = row
                    bar.update(1)
            except KeyboardInterrupt:
                client.cancel(futures)
                raise
            finally:
                bar.close()
    ordered = [rows[r.id] for r in runs]
    write_tables(spec, runs, ordered)
    return StudyResult(spec.directory, ordered, len(todo))


def _progress(total: int, enabled: bool) -> Any:
    from tqdm import tqdm

    return tqdm(total=total, unit="run", desc="study", disable=not enabled)
