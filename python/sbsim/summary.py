"""The run summary (``sbsim --summary FILE.json``): the one module that knows its keys.

The program writes one JSON object at the end of a run::

    {"sbsim": "0.1.0", "sumo": "1.28.0", "command": [...], "sumocfg": "...", "seed": 1,
     "parameters": {"name": value}, "end": {"time": 300.0, "reason": "end time reached"},
     "steps": 300, "vehicles_seen": 150, "peak_running": 40,
     "stories": [{"name": "rain", "activations": 12, "active_vehicle_seconds": 340.0}],
     "signals": {"cause": count}, "services_created": 3,
     "equipped": {"penetration": 0.5, "count": 2, "of": 4,   # with --services: who departed V2X-equipped, when
                  "vehicles": [{"vehicle": "veh0", "since": 0.0}, {"vehicle": "veh3", "since": 2.5}]},
     "messages": {"Type": {"sent": 10, "delivered": 8}},  # also "forwarded" when GeoNetworking forwarded
     "message_trace": {"format": "parquet", "lines": 5000, "bytes": 81234, "max_bytes": 2000000000,
                       "truncated": false, "truncated_at": null},
     "statistics": {"name": {"count": 3, "sum": 9.0, "mean": 3.0, "min": -2.0, "max": 7.0}},
     "criteria": [{"name": "NoCollision()", "passed": true, "actual": "...", "expected": "..."}],
     "verdict": "passed",
     "sumo_warnings": {"total": 2, "kinds": [{"kind": "...", "count": 2}]},
     "held_at_end": {...}, "timing": {"wall_s": ..., "sumo_s": ..., "storyboard_s": ..., ...}}

Readers take the document as :func:`read_summary` returns it (a dict, as written) and ask this
module for what they need: :func:`story_figures` (the report's table), :func:`end_time` (its time
axis), :func:`run_figures` (its run table), :func:`table_columns` (a study's row). The text summary
on stdout is for people (:meth:`sbsim.runner.RunResult.summary` splits it into lines).
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

__all__ = [
    "RUN_FIELDS",
    "StoryFigures",
    "SummaryError",
    "end_time",
    "read_summary",
    "run_figures",
    "story_figures",
    "table_columns",
]

#: A summary as written: the JSON object's keys and values.
Summary = Mapping[str, Any]


class SummaryError(ValueError):
    """A file that is not a run summary: ``path[:line]: what is wrong``."""


def read_summary(path: str | os.PathLike[str]) -> dict[str, Any]:
    """The run's ``--summary`` JSON document.

    Raises :class:`SummaryError` for a file that is not UTF-8, not JSON or not a JSON object, and
    :class:`OSError` for one that cannot be read."""
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except json.JSONDecodeError as e:
        raise SummaryError(f"{os.fspath(path)}:{e.lineno}: bad JSON: {e.msg}") from e
    except UnicodeDecodeError as e:
        raise SummaryError(f"{os.fspath(path)}: not UTF-8 text") from e
    if not isinstance(data, dict):
        raise SummaryError(f"{os.fspath(path)}: not an sbsim summary (not a JSON object)")
    return data


@dataclass(frozen=True)
class StoryFigures:
    """One story's entry of the summary (None where the entry lacks a figure)."""

    name: str
    activations: int | None
    active_vehicle_seconds: float | None


def story_figures(summary: Summary | None) -> dict[str, StoryFigures]:
    """The per-story entries by name, in the summary's order (none without a summary or a usable list)."""
    entries = (summary or {}).get("stories")
    if not isinstance(entries, list):
        return {}
    return {
        e["name"]: StoryFigures(e["name"], e.get("activations"), e.get("active_vehicle_seconds"))
        for e in entries
        if isinstance(e, dict) and isinstance(e.get("name"), str)
    }


def end_time(summary: Summary | None) -> float | None:
    """When the run ended [s] (None if the summary does not say)."""
    end = (summary or {}).get("end")
    time = end.get("time") if isinstance(end, dict) else None
    return float(time) if isinstance(time, int | float) and not isinstance(time, bool) else None


#: The run-level entries, in the order a table shows them, with their labels.
RUN_FIELDS = (
    ("sumocfg", "sumocfg"),
    ("sumo", "SUMO"),
    ("seed", "seed"),
    ("parameters", "parameters"),
    ("end", "end"),
    ("steps", "steps"),
    ("vehicles_seen", "vehicles seen"),
    ("peak_running", "peak running"),
    ("messages", "messages"),
    ("message_trace", "message trace"),
    ("timing", "timing"),
)


def run_figures(summary: Summary) -> dict[str, Any]:
    """The run-level entries the summary has (:data:`RUN_FIELDS`), by label, as written."""
    return {label: summary[key] for key, label in RUN_FIELDS if key in summary}


def table_columns(summary: Summary) -> dict[str, Any]:
    """The summary as one table row: counts, the equipped vehicles (``equipped``, of ``vehicles_seen``;
    with services), per-story activations and active vehicle-seconds, signals per cause, messages per type,
    per statistic ``stat:<name>:<count|sum|mean|min|max>``, the time in SUMO and in the storyboard."""
    row: dict[str, Any] = {k: summary[k] for k in ("steps", "vehicles_seen", "peak_running") if k in summary}
    end = summary.get("end")
    row["end_reason"] = end.get("reason") if isinstance(end, dict) else None
    equipped = summary.get("equipped")
    if isinstance(equipped, dict):
        row["equipped"] = equipped.get("count")
    for story in story_figures(summary).values():
        row[f"activations:{story.name}"] = story.activations
        row[f"active_vehicle_s:{story.name}"] = story.active_vehicle_seconds
    for cause, count in summary.get("signals", {}).items():
        row[f"signals:{cause}"] = count
    for kind, counts in summary.get("messages", {}).items():
        row[f"sent:{kind}"] = counts["sent"]
        row[f"delivered:{kind}"] = counts["delivered"]
        if "forwarded" in counts:
            row[f"forwarded:{kind}"] = counts["forwarded"]
        if "mean_receivers" in counts:
            row[f"mean_receivers:{kind}"] = counts["mean_receivers"]
    trace = summary.get("message_trace")
    if isinstance(trace, dict):
        # None: the trace is whole; a time: the budget ended it there.
        row["messages_truncated_at"] = trace.get("truncated_at")
    if "channel_busy_ratio" in summary:
        row["cbr_mean"] = summary["channel_busy_ratio"]["mean"]
        row["cbr_max"] = summary["channel_busy_ratio"]["max"]
    for name, aggregate in summary.get("statistics", {}).items():
        for figure in ("count", "sum", "mean", "min", "max"):
            row[f"stat:{name}:{figure}"] = aggregate.get(figure)
    if summary.get("criteria"):
        row["verdict"] = summary.get("verdict")
        for criterion in summary["criteria"]:
            row[f"criterion:{criterion['name']}"] = criterion["passed"]
    timing = summary.get("timing", {})
    row["sumo_s"] = timing.get("sumo_s")
    row["storyboard_s"] = timing.get("storyboard_s")
    return row
