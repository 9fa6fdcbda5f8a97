"""A study's results as tables (Parquet) and plots."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from sbsim.events import read_events
from sbsim.messages import read_messages
from sbsim.study.spec import Run, StudySpec

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
    the study keeps them, messages.parquet (their message traces, every field) and statistics.parquet."""
    import pyarrow.parquet as pq

    spec.directory.mkdir(parents=True, exist_ok=True)
    pq.write_table(table_of(list(rows)), spec.directory / "runs.parquet")
    readers = {"events": read_events, "messages": read_messages} if spec.messages else {"events": read_events}
    for name, read in readers.items():
        lines: list[dict[str, Any]] = []
        for r, row in zip(runs, rows, strict=True):
            if row["exit_code"] not in COMPLETE:
                continue
            path = spec.directory / "runs" / r.id / f"{name}.jsonl"
            if not path.exists():
                continue
            context = {"run": r.id, **dict(r.parameters), "seed": r.seed}
            lines.extend({**context, **line} for line in read(path))
        pq.write_table(table_of(lines), spec.directory / f"{name}.parquet")
    if spec.statistics:
        write_statistics(spec, runs, rows)


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
