"""A study's results as tables (Parquet) and plots."""

from __future__ import annotations

import os
import shutil
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from sbsim.events import read_events
from sbsim.study.spec import Run, StudyError, StudySpec

#: Exit codes of runs that went to their end: 0, and 3 (a scenario criterion failed; the verdict is a column).
COMPLETE = (0, 3)


def table_of(records: Sequence[dict[str, Any]]) -> Any:
    """A pyarrow table with a column for every key of any record (first seen first), None where a
    record lacks it: pyarrow's from_pylist takes the columns from the first record only, so a
    signal's cause or a deactivation's reason would vanish behind a first activation."""
    import pyarrow as pa

    keys = list(dict.fromkeys(k for record in records for k in record))
    return pa.table({k: [record.get(k) for record in records] for k in keys})


def write_tables(spec: StudySpec, runs: Sequence[Run], rows: Sequence[dict[str, Any]]) -> None:
    """runs.parquet (one row per run), events.parquet (the complete runs' events, every field) and, when
    the study keeps them, messages/ (their message traces, a dataset partitioned by run) and statistics.parquet."""
    import pyarrow.parquet as pq

    spec.directory.mkdir(parents=True, exist_ok=True)
    pq.write_table(table_of(list(rows)), spec.directory / "runs.parquet")
    lines: list[dict[str, Any]] = []
    for r, row in zip(runs, rows, strict=True):
        path = spec.directory / "runs" / r.id / "events.jsonl"
        if row["exit_code"] not in COMPLETE or not path.exists():
            continue
        context = {"run": r.id, **dict(r.parameters), "seed": r.seed}
        lines.extend({**context, **line} for line in read_events(path))
    pq.write_table(table_of(lines), spec.directory / "events.parquet")
    if spec.messages:
        write_messages(spec, runs, rows)
    if spec.statistics:
        write_statistics(spec, runs, rows)


def write_messages(spec: StudySpec, runs: Sequence[Run], rows: Sequence[dict[str, Any]]) -> None:
    """messages/: every complete run's Parquet message trace as one dataset partitioned by run,
    ``messages/run=<id>/part-0.parquet``, each a hard link to the run's own ``messages.parquet`` (a copy where
    the file system has none), so no trace is read or held: a run's parameters and seed are its row of
    runs.parquet (join on ``run``). :func:`sbsim.messages.read_messages` reads it, by columns and filters."""
    target = spec.directory / "messages"
    shutil.rmtree(target, ignore_errors=True)
    (spec.directory / "messages.parquet").unlink(missing_ok=True)  # the single table of earlier versions
    target.mkdir(parents=True)
    for r, row in zip(runs, rows, strict=True):
        source = spec.directory / "runs" / r.id / "messages.parquet"
        if row["exit_code"] not in COMPLETE or not source.is_file():
            continue
        part = target / f"run={r.id}"
        part.mkdir()
        try:
            os.link(source, part / "part-0.parquet")
        except OSError:
            shutil.copyfile(source, part / "part-0.parquet")


def write_statistics(spec: StudySpec, runs: Sequence[Run], rows: Sequence[dict[str, Any]]) -> None:
    """statistics.parquet: every complete run's --statistics rows (vehicle, service or story, name, time,
    value), each with its run's id, parameters and seed in front."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    parts = []
    for r, row in zip(runs, rows, strict=True):
        path = spec.directory / "runs" / r.id / "statistics.parquet"
        if row["exit_code"] not in COMPLETE or not path.exists():
            continue
        table = pq.read_table(path)
        context = {"run": r.id, **dict(r.parameters), "seed": r.seed}
        for k, (name, value) in enumerate(context.items()):
            table = table.add_column(k, name, pa.array([value] * table.num_rows))
        parts.append(table)
    if parts:
        pq.write_table(pa.concat_tables(parts, promote_options="default"), spec.directory / "statistics.parquet")


def plot(directory: Path, spec: StudySpec) -> list[Path]:
    """Per story, a box plot of its activations over the seeds for each parameter combination."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import pandas as pd

    table = pd.read_parquet(directory / "runs.parquet")
    table = table[table["exit_code"].isin(COMPLETE)]
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


def column_by_parameter(table: Any, column: str, parameters: Sequence[str]) -> Any:
    """``column`` of the complete runs (``runs.parquet``'s rows) over the seeds, per value of the first
    parameter (``x``) and combination of the others (``group``, "" when there is none; ``x`` is the seed in a
    study without parameters): ``mean``, ``std`` (0 for one run), ``min``, ``max`` and ``runs``.

    Raises :class:`StudyError` for a column the table lacks or that is not numeric."""
    import pandas as pd

    if column not in table.columns:
        known = ", ".join(c for c in table.columns if c.startswith(("stat:", "activations:"))) or "none"
        raise StudyError(f"--plot: runs.parquet has no column '{column}' (statistics and activations: {known})")
    done = table[table["exit_code"].isin(COMPLETE)]
    values = pd.to_numeric(done[column], errors="coerce")
    if values.isna().all() and len(done):
        raise StudyError(f"--plot: column '{column}' holds no numbers")
    x = parameters[0] if parameters else "seed"
    others = list(parameters[1:])
    group = done[others].astype(str).agg(", ".join, axis=1) if others else pd.Series("", index=done.index)
    frame = pd.DataFrame({"group": group, "x": done[x], "value": values})
    out = frame.groupby(["group", "x"], sort=True)["value"].agg(["mean", "std", "min", "max", "count"])
    out = out.rename(columns={"count": "runs"}).reset_index()
    out["std"] = out["std"].fillna(0.0)
    return out


def draw_column(data: Any, column: str, parameters: Sequence[str]) -> Any:
    """A figure of :func:`column_by_parameter`'s ``data``: per group one line of the means against ``x``
    with the seeds' standard deviation as error bars (labelled with the group, or ``column``)."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(6.4, 4.2), layout="constrained")
    ax = fig.add_subplot()
    x_name = parameters[0] if parameters else "seed"
    others = ", ".join(parameters[1:])
    for i, (group, rows) in enumerate(data.groupby("group", sort=True)):
        label = f"{others} = {group}" if group else column
        ax.errorbar(
            rows["x"].astype(str) if rows["x"].dtype == object else rows["x"],
            rows["mean"],
            yerr=rows["std"],
            marker="o",
            capsize=3,
            color=f"C{i % 10}",
            label=label,
        )
    ax.set_xlabel(x_name)
    ax.set_ylabel(column)
    runs = int(data["runs"].max()) if len(data) else 0
    ax.set_title(f"{column} against {x_name}" + (f" (mean ± sd over up to {runs} seeds)" if parameters else ""))
    ax.legend(loc="best")
    return fig


def plot_column(directory: Path, spec: StudySpec, column: str) -> Path:
    """Draws ``column`` of runs.parquet against the study's first parameter as ``plot-<column>.png``."""
    import pandas as pd

    names = list(spec.parameters)
    data = column_by_parameter(pd.read_parquet(directory / "runs.parquet"), column, names)
    path = directory / f"plot-{''.join(c if c.isalnum() else '_' for c in column)}.png"
    draw_column(data, column, names).savefig(path, dpi=100)
    return path
