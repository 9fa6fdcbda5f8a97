"""Running a study: one ``sbsim`` process per run, started by a Dask task, each in its own folder."""

from __future__ import annotations

import asyncio
import hashlib
import json
import logging
import os
import signal
import subprocess
import tempfile
import threading
import time
import uuid
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from sbsim.runner import executable
from sbsim.study.junit import write_junit
from sbsim.study.spec import Run, StudyError, StudySpec
from sbsim.study.tables import COMPLETE, write_tables
from sbsim.summary import read_summary, table_columns

#: How much of a failed run's stderr its row keeps.
STDERR_TAIL = 2000

#: sbsim's exit code for a run that went to its end with a criterion failed.
CRITERION_FAILED = 3

#: sbsim's exit code for a run stopped by SIGINT or SIGTERM: the run is not finished, it is done again.
INTERRUPTED = 130

#: Seconds the runs of a stopped study (and a run past --timeout) have, after SIGINT / SIGTERM, to reach a
#: safe point and exit before they are killed.
STOP_GRACE = 5.0

#: A run's record, written last: the row and the size and SHA-256 of each output it wrote.
RESULT = "result.json"


def check_radio(spec: StudySpec, program: str) -> None:
    """Before the first run: the radio file and every ``radio_*`` value of the sweep as sbsim reads them
    (``sbsim check`` with the services and radio file, each value alone), so that a mistake in the study file
    ends the study at once, one line, instead of failing every run that takes it. Raises StudyError."""
    if spec.radio is None or spec.services is None:
        return
    base = [program, "check", "--sumocfg", str(spec.sumocfg), "--services", str(spec.services)]
    base += ["--radio", str(spec.radio)]
    for plugin in spec.plugins:
        base += ["--plugin", str(plugin)]
    variants: list[list[str]] = [[]]
    for name, values in spec.parameters.items():
        if name.startswith("radio_"):
            # As a run passes it (Run.arguments), without the seed.
            variants += [Run(((name, v),), 0).arguments()[2:] for v in dict.fromkeys(values)]
    with tempfile.TemporaryDirectory(prefix="sbsim-study-check-") as scratch:
        for variant in variants:
            if (message := _refused(base + variant, scratch)) is not None:
                raise StudyError(f"{' '.join(variant[1:]) or str(spec.radio)}: {message}")


def _refused(check: list[str], scratch: str) -> str | None:
    """Runs an ``sbsim check`` command line in `scratch`: None if it passed (criteria aside), else sbsim's
    last line (the reason)."""
    done = subprocess.run(
        check,
        cwd=scratch,
        env=_environment(),
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        errors="replace",
        check=False,
    )
    if done.returncode in (0, 3):
        return None
    lines = [line for line in done.stderr.splitlines() if line.strip() and "warning" not in line]
    return lines[-1].removeprefix("sbsim: ") if lines else f"sbsim check exited {done.returncode}"


def check_study(spec: StudySpec, program: str) -> int:
    """The whole study file as sbsim reads it, running nothing: the radio settings of every sweep value
    (:func:`check_radio`), then ``sbsim check`` on each distinct combination of the parameters (the first seed):
    story, services, radio file, plugins and the run's arguments. Returns the number of runs the study has;
    raises StudyError with sbsim's one line for the first combination it refuses."""
    check_radio(spec, program)
    runs = spec.runs()
    first_seed = {run.parameters: run for run in runs}
    with tempfile.TemporaryDirectory(prefix="sbsim-study-check-") as scratch:
        for run in first_seed.values():
            cmd = spec.command(run, Path(scratch), program)
            if (message := _refused([cmd[0], "check", *cmd[1:]], scratch)) is not None:
                raise StudyError(f"run {run.id}: {message}")
    return len(runs)


def outputs(spec: StudySpec) -> tuple[str, ...]:
    """The files sbsim writes into each run's folder for the study (checked when the study resumes)."""
    kept = (("messages.parquet",) if spec.messages else ()) + (("statistics.parquet",) if spec.statistics else ())
    return ("events.jsonl", "summary.json", *kept)


def digest(path: Path) -> str:
    """The file's SHA-256, read in blocks (a trace may be large)."""
    h = hashlib.sha256()
    with open(path, "rb") as f:
        while block := f.read(1 << 20):
            h.update(block)
    return h.hexdigest()


def result_of(folder: Path) -> dict[str, Any] | None:
    """A finished run's row, or None if the folder does not hold what the run left: not run, stopped
    half-way, a ``*.incomplete`` file left, an output missing or not byte for byte what the run wrote (its
    size and SHA-256 are recorded: a damaged file of the right size is caught too), or a record from before
    outputs were recorded so. Such a run is done again."""
    try:
        saved = json.loads((folder / RESULT).read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError):
        return None
    if not isinstance(saved, dict) or not isinstance(saved.get("row"), dict):
        return None
    recorded = saved.get("outputs")
    if not isinstance(recorded, dict) or any(folder.glob("*.incomplete")):
        return None
    for name, record in recorded.items():
        if not isinstance(record, dict) or not isinstance(record.get("sha256"), str):
            return None
        try:
            if (folder / name).stat().st_size != record.get("size") or digest(folder / name) != record["sha256"]:
                return None
        except OSError:
            return None
    return saved["row"]


# The sbsim processes each worker process runs, per study, so that a stopped study can stop them
# (stop_runs, through Client.run) wherever they run, on a local or a remote cluster.
_LOCK = threading.Lock()
_RUNNING: dict[str, set[subprocess.Popen[bytes]]] = {}
_STOPPED: set[str] = set()


def execute(spec: StudySpec, run: Run, program: str, timeout: float | None = None, study: str = "") -> dict[str, Any]:
    """Runs one sbsim process (on a Dask worker) in the run's folder and returns its row; never raises for a
    failed run. A run stopped by a signal (exit 130, or its study stopped: see stop_runs) records nothing,
    so the study does it again."""
    folder = spec.directory / "runs" / run.id
    row: dict[str, Any] = {"run": run.id, **dict(run.parameters), "seed": run.seed}
    try:
        folder.mkdir(parents=True, exist_ok=True)
        # A run done again starts clean: no old record saying it finished, no stale partial outputs.
        (folder / RESULT).unlink(missing_ok=True)
        for stale in folder.glob("*.incomplete"):
            stale.unlink(missing_ok=True)
    except OSError as e:  # e.g. a file where the folder should be: the run fails, the study goes on
        return {**row, "exit_code": 2, "stderr_tail": f"study: the run's folder {folder}: {e.strerror}"}
    started = time.monotonic()
    timed_out = False
    with open(folder / "stderr.txt", "wb") as err:
        with _LOCK:
            if study in _STOPPED:
                return {**row, "exit_code": INTERRUPTED}
            proc = subprocess.Popen(
                spec.command(run, folder, program),
                cwd=folder,
                env=_environment(),
                stdin=subprocess.DEVNULL,
                stdout=subprocess.DEVNULL,
                stderr=err,
            )
            _RUNNING.setdefault(study, set()).add(proc)
        try:
            code = proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            timed_out = True
            proc.terminate()  # sbsim stops at its next safe point, leaving only *.incomplete
            try:
                proc.wait(timeout=STOP_GRACE)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
            code = -1
        finally:
            with _LOCK:
                _RUNNING[study].discard(proc)
                if not _RUNNING[study]:
                    del _RUNNING[study]
                stopped = study in _STOPPED
    row["exit_code"] = code
    if stopped or code == INTERRUPTED:
        return row
    stderr = (folder / "stderr.txt").read_text(encoding="utf-8", errors="replace")
    if timed_out:
        stderr += f"study: the run took longer than {timeout} s\n"
        (folder / "stderr.txt").write_text(stderr, encoding="utf-8")
    row["wall_s"] = round(time.monotonic() - started, 3)
    row["stderr_tail"] = stderr[-STDERR_TAIL:] if code not in COMPLETE else ""
    summary = folder / "summary.json"
    if code in COMPLETE and summary.exists():
        row.update(table_columns(read_summary(summary)))
    written = {
        name: {"size": (folder / name).stat().st_size, "sha256": digest(folder / name)}
        for name in outputs(spec)
        if (folder / name).is_file()
    }
    # Written last, through a rename: its presence says the run is finished.
    tmp = folder / f"{RESULT}.tmp"
    tmp.write_text(json.dumps({"row": row, "outputs": written}), encoding="utf-8")
    tmp.replace(folder / RESULT)
    return row


def _environment() -> dict[str, str]:
    """The worker's environment, with PYTHONPATH's folders absolute: a run works in its own folder, and
    a relative entry must keep meaning the folder it meant where the worker started."""
    env = dict(os.environ)
    if env.get("PYTHONPATH"):
        env["PYTHONPATH"] = os.pathsep.join(os.path.abspath(p or ".") for p in env["PYTHONPATH"].split(os.pathsep))
    return env


async def stop_runs(study: str, grace: float = STOP_GRACE) -> int:
    """Run on every worker by a stopped study (``Client.run``): no further run of the study starts there,
    and its running sbsim processes get SIGINT (they stop at their next safe point, leaving only
    ``*.incomplete``), SIGKILL if still running after grace seconds. Returns how many it stopped."""
    with _LOCK:
        _STOPPED.add(study)
        procs = list(_RUNNING.get(study, ()))
    for proc in procs:
        proc.send_signal(signal.SIGINT)
    deadline = time.monotonic() + grace
    # returncode is set by the thread waiting for the process (execute): this one never reaps it.
    while time.monotonic() < deadline and any(p.returncode is None for p in procs):
        await asyncio.sleep(0.05)
    for proc in procs:
        if proc.returncode is None:
            proc.kill()
    return len(procs)


class StudyInterrupted(Exception):
    """The study was stopped (SIGINT, SIGTERM) and its running runs with it; finished runs are kept."""

    def __init__(self, finished: int, total: int) -> None:
        super().__init__(f"{finished} of {total} runs finished")
        self.finished = finished
        self.total = total


@dataclass
class StudyResult:
    directory: Path
    rows: list[dict[str, Any]]
    ran: int  # runs executed now (the others were complete already)

    @property
    def failed(self) -> list[dict[str, Any]]:
        return [r for r in self.rows if r["exit_code"] not in COMPLETE]

    @property
    def failed_criteria(self) -> list[dict[str, Any]]:
        """The complete runs of which a criterion failed (sbsim's exit code 3)."""
        return [r for r in self.rows if r["exit_code"] == CRITERION_FAILED]


@contextmanager
def _local_workers_quiet() -> Iterator[None]:
    """While a LocalCluster starts its worker processes: they ignore SIGINT (a Ctrl-C reaches the whole
    process group; the study stops their runs itself, and a worker would print a KeyboardInterrupt
    traceback) and log only errors (a stopped study's cancelled tasks are warnings)."""
    os.environ["DASK_LOGGING__DISTRIBUTED"], previous_level = "error", os.environ.get("DASK_LOGGING__DISTRIBUTED")
    main = threading.current_thread() is threading.main_thread()
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN) if main else None
    try:
        yield
    finally:
        if previous is not None:
            signal.signal(signal.SIGINT, previous)
        if previous_level is None:
            del os.environ["DASK_LOGGING__DISTRIBUTED"]
        else:
            os.environ["DASK_LOGGING__DISTRIBUTED"] = previous_level


@contextmanager
def _cluster(scheduler: str | None, workers: int | None) -> Iterator[Any]:
    from distributed import Client, LocalCluster

    if scheduler:
        with Client(scheduler) as client:
            yield client
        return
    n = workers or os.cpu_count() or 1
    with _local_workers_quiet():
        cluster = LocalCluster(
            n_workers=n, threads_per_worker=1, processes=True, dashboard_address=":0", silence_logs=logging.ERROR
        )
    with cluster, Client(cluster) as client:
        yield client


class _Stopping:
    """From begin() to the end of the with block (the cluster closed): SIGINT and SIGTERM are ignored, as
    a second Ctrl-C while a stopped study stops its runs (a few seconds) would leave them running."""

    def __init__(self) -> None:
        self.previous: dict[int, Any] = {}

    def begin(self) -> None:
        if threading.current_thread() is threading.main_thread() and not self.previous:
            self.previous = {s: signal.signal(s, signal.SIG_IGN) for s in (signal.SIGINT, signal.SIGTERM)}

    def __enter__(self) -> _Stopping:
        return self

    def __exit__(self, *exc: object) -> None:
        for s, handler in self.previous.items():
            signal.signal(s, handler)


def run(
    spec: StudySpec,
    *,
    scheduler: str | None = None,
    workers: int | None = None,
    progress: bool = True,
    timeout: float | None = None,
    check: bool = True,
) -> StudyResult:
    """Runs the study's missing runs on Dask, then writes runs.parquet, events.parquet and junit.xml;
    first, with ``check``, the radio settings of the study file (:func:`check_radio`).

    KeyboardInterrupt (SIGINT) stops the runs under way (see stop_runs) and raises StudyInterrupted."""
    from distributed import as_completed

    program = str(executable().resolve())
    if check:  # the command checks before it makes the output folder
        check_radio(spec, program)
    runs = spec.runs()
    rows: dict[str, dict[str, Any]] = {}
    todo = []
    for r in runs:
        done = result_of(spec.directory / "runs" / r.id)
        if done is not None and done.get("exit_code") in COMPLETE:
            rows[r.id] = done
        else:
            todo.append(r)
    study = uuid.uuid4().hex
    try:
        if todo:
            with _Stopping() as stopping, _cluster(scheduler, workers) as client:
                if progress and client.dashboard_link:
                    print(
                        f"study: {len(todo)} of {len(runs)} runs to do; dashboard {client.dashboard_link}", flush=True
                    )
                futures: list[Any] = []
                bar = _progress(len(todo), enabled=progress)
                try:
                    futures = [
                        client.submit(execute, spec, r, program, timeout, study, key=f"sbsim-{r.id}", pure=False)
                        for r in todo
                    ]
                    for future in as_completed(futures):
                        row = future.result()
                        rows[row["run"]] = row
                        bar.update(1)
                except BaseException:
                    # Interrupted, or an error in the study itself: no run may go on without it.
                    stopping.begin()
                    bar.close()
                    try:
                        client.cancel([f for f in futures if not f.done()])  # those not started never start
                        client.run(stop_runs, study)  # those under way stop
                    except Exception:  # noqa: S110 -- the cluster broke: what stopped the study is the news
                        pass
                    raise
                finally:
                    bar.close()
    except KeyboardInterrupt:
        finished = sum(1 for r in runs if rows.get(r.id, {}).get("exit_code") in COMPLETE)
        raise StudyInterrupted(finished, len(runs)) from None
    ordered = [rows[r.id] for r in runs]
    write_tables(spec, runs, ordered)
    write_junit(spec, runs, ordered)
    return StudyResult(spec.directory, ordered, len(todo))


def _progress(total: int, enabled: bool) -> Any:
    from tqdm import tqdm

    return tqdm(total=total, unit="run", desc="study", disable=not enabled)
