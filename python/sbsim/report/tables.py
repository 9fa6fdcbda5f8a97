"""The report's two tables: per story (from the log, beside the summary's figures) and the run's figures."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import pandas as pd

from sbsim.report.analysis import Events, events_frame, stays, stories, world_stories
from sbsim.summary import run_figures, story_figures


def story_table(
    events: Events, summary: Mapping[str, Any] | None = None, names: Sequence[str] | None = None
) -> pd.DataFrame:
    """Per story: its kind (``vehicle``, or ``world`` for a WorldStory, whose lines have no vehicle),
    activations, vehicles (none for a world story), completed stays, their mean duration, stays still
    open at the end; with the summary, its activation count and active vehicle-seconds beside them."""
    frame = events_frame(events)
    names = list(names) if names is not None else stories(frame, summary)
    table = stays(frame)
    world = set(world_stories(frame))
    rows = []
    for name in names:
        mine = table[table["story"] == name]
        done = mine["duration"].dropna()
        rows.append(
            {
                "story": name,
                "kind": "world" if name in world else "vehicle",
                "activations": len(mine),
                # A world story's periods have no vehicle: none to count.
                "vehicles": math.nan if name in world else mine["vehicle"].nunique(),
                "completed stays": len(done),
                "mean duration [s]": done.mean() if len(done) else math.nan,
                "active at the end": len(mine) - len(done),
            }
        )
    out = pd.DataFrame(
        rows,
        columns=[
            "story",
            "kind",
            "activations",
            "vehicles",
            "completed stays",
            "mean duration [s]",
            "active at the end",
        ],
    ).set_index("story")
    if summary is not None:
        figures = story_figures(summary)
        found = [figures.get(n) for n in out.index]
        out["activations (summary)"] = [f.activations if f else None for f in found]
        out["active vehicle-seconds (summary)"] = [f.active_vehicle_seconds if f else None for f in found]
    return out


def run_table(summary: Mapping[str, Any]) -> pd.DataFrame:
    """The summary's run-level figures (seed, end, steps, vehicles, messages, timing) as one column."""
    rows: dict[str, str] = {}
    for label, value in run_figures(summary).items():
        if label == "end" and isinstance(value, dict):
            rows[label] = f"{value.get('time')} s ({value.get('reason')})"
        elif isinstance(value, dict):
            rows[label] = ", ".join(f"{k}: {_short(v)}" for k, v in value.items()) or "none"
        else:
            rows[label] = str(value)
    return pd.DataFrame({"value": rows}).rename_axis("run")


def _short(value: Any) -> str:
    return f"{value:.3g}" if isinstance(value, float) else str(value)
