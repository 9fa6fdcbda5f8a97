"""Studies: one story run over parameter values x seeds, on Dask, with the results as two tables.

    python -m storyboard.study study.toml [--scheduler tcp://host:8786] [--workers N] [--plot]

The TOML names the scenario, the seeds and the parameter values (paths relative to the TOML)::

    sumocfg = "grid-rain.sumocfg"
    story = "story.py"                  # optional; also: services = "services.xml", radio = "radio.toml"
    seeds = { first = 1, count = 10 }   # or a list: seeds = [1, 2, 3]
    end = 600                           # optional; also: args = ["--threads", "1"]
    [parameters]
    rain_speed = [5, 10, 15]
    [outputs]
    directory = "results/rain"
    messages = false                    # true: every run's --messages trace, and messages.parquet

Each run is one ``sbsim`` process (crash isolation; SUMO is not re-entrant) started by a Dask task,
on a ``distributed.LocalCluster`` with one single-threaded worker process per core, or on an
existing cluster (``--scheduler``; workers must see the same file system). Every run writes its
own folder ``runs/<id>/`` (events.jsonl, summary.json, stderr, result.json, written last); a run whose
result.json says it succeeded is not run again, so an interrupted study resumes where it stopped.
At the end ``runs.parquet`` (one row per run) and ``events.parquet`` (every event with its run's
parameters and seed) are written beside them, and with ``messages = true`` ``messages.parquet`` (every
line of the runs' message traces, likewise).
"""

from __future__ import annotations

import argparse
import hashlib
import itertools
import json
import os
import subprocess
import sys
import time
import tomllib
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from storyboard.runner import executable

#: A parameter value as sbsim's --param types it.
Value = bool | int | float | str

#: How much of a failed run's stderr its row keeps.
STDERR_TAIL = 2000


class StudyError(ValueError):
    """A study file that cannot be run as it is (one line saying what and where)."""


@dataclass(frozen=True)
class Run:
    """One run of a study: its parameter values and seed."""

    parameters: tuple[tuple[str, Value], ...]
    seed: int

    @property
    def id(self) -> str:
        """Readable and stable: the values and seed, with a short hash so odd values stay unique."""
        text = json.dumps([list(self.parameters), self.seed])
        readable = "_".join(f"{k}-{v}" for k, v in self.parameters) + f"_seed-{self.seed}"
        safe = "".join(c if c.isalnum() or c in "-_." else "+" for c in readable)[:80]
        return f"{safe}_{hashlib.sha1(text.encode()).hexdigest()[:8]}"

    def arguments(self) -> list[str]:
        out = ["--seed", str(self.seed)]
        for name, value in self.parameters:
            out += ["--param", f"{name}={str(value).lower() if isinstance(value, bool) else value}"]
        return out


@dataclass(frozen=True)
class StudySpec:
    sumocfg: Path
    directory: Path
    seeds: tuple[int, ...]
    parameters: dict[str, list[Value]] = field(default_factory=dict)
    story: Path | None = None
    services: Path | None = None
    radio: Path | None = None
    messages: bool = False
    end: float | None = None
    args: tuple[str, ...] = ()

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> StudySpec:
        path = Path(path)
        try:
            data = tomllib.loads(path.read_text(encoding="utf-8"))
        except (OSError, tomllib.TOMLDecodeError, UnicodeDecodeError) as e:
            raise StudyError(f"{path}: {e}") from e
        return cls.from_dict(data, base=path.parent, source=str(path))

    @classmethod
    def from_dict(cls, data: dict[str, Any], base: Path = Path("."), source: str = "study") -> StudySpec:
        known = {"sumocfg", "story", "services", "radio", "seeds", "end", "args", "parameters", "outputs"}
        for key in data:
            if key not in known:
                raise StudyError(f"{source}: unknown key '{key}' (known: {', '.join(sorted(known))})")
        if "sumocfg" not in data:
            raise StudyError(f"{source}: 'sumocfg' is missing")

        def file(key: str) -> Path | None:
            return (base / data[key]).resolve() if key in data else None

        seeds = data.get("seeds", [23423])
        if isinstance(seeds, dict):
            first, count = seeds.get("first", 1), seeds.get("count", 1)
            if not isinstance(first, int) or not isinstance(count, int) or count < 1:
                raise StudyError(f"{source}: seeds needs whole numbers 'first' and 'count' >= 1")
            seeds = list(range(first, first + count))
        if not isinstance(seeds, list) or not seeds or not all(isinstance(s, int) for s in seeds):
            raise StudyError(f"{source}: seeds must be a non-empty list of whole numbers or {{ first, count }}")
        parameters = data.get("parameters", {})
        for name, values in parameters.items():
            if not isinstance(values, list) or not values:
                raise StudyError(f"{source}: parameter '{name}' needs a non-empty list of values")
        outputs = data.get("outputs", {})
        directory = base / outputs.get("directory", "results")
        messages = outputs.get("messages", False)
        if not isinstance(messages, bool):
            raise StudyError(f"{source}: [outputs] messages must be true or false")
        end = data.get("end")
        if end is not None and not isinstance(end, int | float):
            raise StudyError(f"{source}: 'end' must be a number of seconds")
        return cls(
            sumocfg=file("sumocfg") or Path(),
            directory=directory.resolve(),
            seeds=tuple(seeds),
            parameters={k: list(v) for k, v in parameters.items()},
            story=file("story"),
            services=file("services"),
            radio=file("radio"),
            messages=messages,
            end=None if end is None else float(end),
            args=tuple(str(a) for a in data.get("args", [])),
        )

    def runs(self) -> list[Run]:
        """The cartesian product of the parameter values (in the file's order) x the seeds."""
        names = list(self.parameters)
        combos = itertools.product(*(self.parameters[n] for n in names)) if names else [()]
        return [Run(tuple(zip(names, combo, strict=True)), seed) for combo in combos for seed in self.seeds]

    def command(self, run: Run, folder: Path, program: str) -> list[str]:
        cmd = [program, "--sumocfg", str(self.sumocfg), "--events", str(folder / "events.jsonl")]
        cmd += ["--summary", str(folder / "summary.json"), "--quiet"]
        if self.story is not None:
            cmd += ["--story", str(self.story)]
        if self.services is not None:
            cmd += ["--services", str(self.services)]
        if self.radio is not None:
            cmd += ["--radio", str(self.radio)]
        if self.messages:
            cmd += ["--messages", str(folder / "messages.jsonl")]
        if self.end is not None:
            cmd += ["--end", repr(self.end)]
        return cmd + run.arguments() + list(self.args)


def summary_columns(summary: dict[str, Any]) -> dict[str, Any]:
    """A run's --summary JSON as table columns: counts, per-story activations and active
    vehicle-seconds, signals per cause, messages per type, the time in SUMO and in the storyboard."""
    row: dict[str, Any] = {k: summary[k] for k in ("steps", "vehicles_seen", "peak_running") if k in summary}
    row["end_reason"] = summary.get("end", {}).get("reason")
    for story in summary.get("stories", []):
        row[f"activations:{story['name']}"] = story["activations"]
        row[f"active_vehicle_s:{story['name']}"] = story["active_vehicle_seconds"]
    for cause, count in summary.get("signals", {}).items():
        row[f"signals:{cause}"] = count
    for kind, counts in summary.get("messages", {}).items():
        row[f"sent:{kind}"] = counts["sent"]
        row[f"delivered:{kind}"] = counts["delivered"]
        if "mean_receivers" in counts:
            row[f"mean_receivers:{kind}"] = counts["mean_receivers"]
    if "channel_busy_ratio" in summary:
        row["cbr_mean"] = summary["channel_busy_ratio"]["mean"]
        row["cbr_max"] = summary["channel_busy_ratio"]["max"]
    timing = summary.get("timing", {})
    row["sumo_s"] = timing.get("sumo_s")
    row["storyboard_s"] = timing.get("storyboard_s")
    return row


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
    row["stderr_tail"] = stderr[-STDERR_TAIL:] if code != 0 else ""
    summary = folder / "summary.json"
    if code == 0 and summary.exists():
        row.update(summary_columns(json.loads(summary.read_text(encoding="utf-8"))))
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
        return [r for r in self.rows if r["exit_code"] != 0]


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
        if done is not None and done.get("exit_code") == 0:
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


def write_tables(spec: StudySpec, runs: Sequence[Run], rows: Sequence[dict[str, Any]]) -> None:
    """runs.parquet (one row per run), events.parquet (the successful runs' events) and, when the
    study keeps them, messages.parquet (their message traces)."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    spec.directory.mkdir(parents=True, exist_ok=True)
    pq.write_table(pa.Table.from_pylist(list(rows)), spec.directory / "runs.parquet")
    for name in ("events", "messages") if spec.messages else ("events",):
        lines: list[dict[str, Any]] = []
        for r, row in zip(runs, rows, strict=True):
            if row["exit_code"] != 0:
                continue
            path = spec.directory / "runs" / r.id / f"{name}.jsonl"
            if not path.exists():
                continue
            context = {"run": r.id, **dict(r.parameters), "seed": r.seed}
            with path.open(encoding="utf-8") as f:
                lines.extend({**context, **json.loads(line)} for line in f if line.strip())
        pq.write_table(pa.Table.from_pylist(lines), spec.directory / f"{name}.parquet")


def plot(directory: Path, spec: StudySpec) -> list[Path]:
    """Per story, a box plot of its activations over the seeds for each parameter combination."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import pandas as pd

    table = pd.read_parquet(directory / "runs.parquet")
    table = table[table["exit_code"] == 0]
    names = list(spec.parameters)
    labels = table[names].astype(str).agg(", ".join, axis=1) if names else pd.Series("all", index=table.index)
    out = []
    for column in (c for c in table.columns if c.startswith("activations:")):
        story = column.removeprefix("activations:")
        groups = {label: table.loc[labels == label, column].to_list() for label in dict.fromkeys(labels)}
        fig, ax = plt.subplots(figsize=(max(4.0, 1.2 * len(groups)), 4.0))
        ax.boxplot(list(groups.values()))
        ax.set_xticks(range(1, len(groups) + 1), list(groups.keys()), rotation=30, ha="right")
        ax.set_xlabel(", ".join(names) or "runs")
        ax.set_ylabel("activations")
        ax.set_title(f"{story}: activations over {len(spec.seeds)} seeds")
        fig.tight_layout()
        path = directory / f"activations-{''.join(c if c.isalnum() else '_' for c in story)}.png"
        fig.savefig(path, dpi=100)
        plt.close(fig)
        out.append(path)
    return out


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m storyboard.study", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("study", type=Path, help="the study's TOML file")
    parser.add_argument("--scheduler", help="address of a running Dask scheduler (default: a local cluster)")
    parser.add_argument("--workers", type=int, help="local worker processes (default: one per core)")
    parser.add_argument("--timeout", type=float, help="seconds a single run may take (default: no limit)")
    parser.add_argument("--plot", action="store_true", help="also draw activations per story (PNG files)")
    args = parser.parse_args(argv)
    try:
        spec = StudySpec.load(args.study)
        if args.workers is not None and args.workers < 1:
            raise StudyError("--workers must be >= 1")
        result = run(spec, scheduler=args.scheduler, workers=args.workers, timeout=args.timeout)
    except StudyError as e:
        print(f"study: {e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("study: interrupted; finished runs are kept, run the same command again to go on", file=sys.stderr)
        return 130
    print(f"study: {len(result.rows)} runs ({result.ran} run now, {len(result.failed)} failed) in {spec.directory}")
    for row in result.failed:
        print(f"study: run {row['run']} failed with exit code {row['exit_code']}", file=sys.stderr)
    if args.plot:
        for path in plot(spec.directory, spec):
            print(f"study: plot {path}")
    return 1 if result.failed else 0


if __name__ == "__main__":
    sys.exit(main())
