"""Watching a story: what one run's stories did, as figures and a table in one HTML file.

    python -m storyboard.report events.jsonl --sumocfg C [--story S [--param N=V]] [--fcd f.xml] [--summary s.json]
        -o report.html [--png DIR]

Figures (also as functions returning :class:`matplotlib.figure.Figure`):

1. :func:`plot_activity`: vehicles under each story over time, stacked and step-wise, from the
   activate / deactivate events;
2. :func:`plot_durations`: how long each stay under a story lasted (one histogram per story; stays
   still open when the log ends have no length and are only counted in the title);
3. :func:`plot_map`: the network's lanes (the sumocfg's ``net-file``, read with sumolib), with
   ``--story`` each story's areas, and where vehicles were when each story activated for them;
4. :func:`plot_speeds` (needs ``--fcd``): mean speed per time step of the vehicles under each story
   against the other running vehicles.

Where stories act: the event log and the summary carry neither the stories' areas nor positions
(an event is ``t``, ``type``, ``story``, ``vehicle``). The areas live in the story script, which
needs sbsim's compiled module to load, so with ``--story`` (and the run's ``--param`` values, if the
script reads them) the report runs ``sbsim check --json`` (the executable
:func:`storyboard.runner.executable` finds) and draws every ``PolygonCondition`` as a filled polygon
and every ``DistanceCondition`` around a point as a circle, in the story's colour and in SUMO's
frame whatever frame the script used (:func:`story_areas`). The activation positions are what the
run itself recorded: read from SUMO's FCD output (``--sumo-option "--fcd-output f.xml"``) at the
activation time. Without ``--story`` and ``--fcd`` the map shows the network only. SUMO labels an
FCD state with the time at the start of its step, sbsim the time after it, so FCD time ``T`` is
sbsim time ``T + step`` (the step is the FCD's own spacing, else the sumocfg's ``step-length``, else
1 s).

Bad input (a missing or unreadable file, a line of the log that is not an event, a broken sumocfg,
net, FCD or summary, a story script ``sbsim check`` rejects) is one line on stderr naming the file,
and exit code 2.
"""

from __future__ import annotations

import argparse
import base64
import html
import io
import json
import math
import os
import subprocess
import sys
import xml.sax
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd
import sumolib
from matplotlib.collections import LineCollection
from matplotlib.colors import to_rgba
from matplotlib.figure import Figure
from matplotlib.patches import Circle, Polygon

from storyboard import runner
from storyboard.runner import EventLogError, read_events, read_summary

#: Events as :func:`storyboard.runner.read_events` returns them, or the same as a DataFrame.
Events = Sequence[dict[str, Any]] | pd.DataFrame

PROG = "python -m storyboard.report"


class ReportError(ValueError):
    """An input the report cannot use (one line naming the file)."""


# ---------------------------------------------------------------------------------------------------------------------
# Reading


def events_frame(events: Events) -> pd.DataFrame:
    """The events as a DataFrame (columns ``t``, ``type``, ``story``, ``vehicle`` at least), in log order."""
    frame = events.copy() if isinstance(events, pd.DataFrame) else pd.DataFrame(list(events))
    for column in ("t", "type", "story", "vehicle"):
        if column not in frame:
            frame[column] = pd.Series(dtype="float64" if column == "t" else "object")
    # Rounded like sbsim's log (1 ms), so times compare equal to the FCD's.
    frame["t"] = frame["t"].astype("float64").round(3)
    return frame.reset_index(drop=True)


def stories(events: Events, summary: dict[str, Any] | None = None) -> list[str]:
    """Story names in the order they first appear in the log, then those only the summary lists."""
    names = list(dict.fromkeys(events_frame(events)["story"]))
    names += [name for name in summary_stories(summary) if name not in names]
    return names


def summary_stories(summary: dict[str, Any] | None) -> dict[str, dict[str, Any]]:
    """The summary's per-story entries by name (none if there is no summary or it has no usable list)."""
    entries = (summary or {}).get("stories")
    if not isinstance(entries, list):
        return {}
    return {e["name"]: e for e in entries if isinstance(e, dict) and isinstance(e.get("name"), str)}


def stays(events: Events) -> pd.DataFrame:
    """One row per activation: ``story``, ``vehicle``, ``start``, ``end`` (NaN while still active at the
    end of the log), ``duration`` (NaN likewise) and ``reason`` (the deactivation's)."""
    frame = events_frame(events)
    keys = ["story", "vehicle"]
    on = frame[frame["type"] == "activate"][[*keys, "t"]].rename(columns={"t": "start"})
    off = frame[frame["type"] == "deactivate"][[*keys, "t"]].rename(columns={"t": "end"})
    if "reason" in frame:
        off["reason"] = frame.loc[off.index, "reason"]
    else:
        off["reason"] = pd.Series(dtype="object")
    # The n-th deactivation of a story for a vehicle closes its n-th activation.
    # dropna=False: a WorldStory's lines have no vehicle.
    on["n"] = on.groupby(keys, dropna=False).cumcount()
    off["n"] = off.groupby(keys, dropna=False).cumcount()
    out = on.merge(off, on=[*keys, "n"], how="left").drop(columns="n")
    out["duration"] = out["end"] - out["start"]
    return out.reset_index(drop=True)


def active_counts(events: Events, names: Sequence[str] | None = None) -> pd.DataFrame:
    """Vehicles under each story after the evaluation at every time where some count changes: indexed
    by time, one column per story."""
    frame = events_frame(events)
    names = list(names) if names is not None else stories(frame)
    changes = frame[frame["type"].isin(["activate", "deactivate"])]
    delta = changes["type"].map({"activate": 1, "deactivate": -1})
    table = (
        pd.DataFrame({"t": changes["t"], "story": changes["story"], "delta": delta})
        .pivot_table(index="t", columns="story", values="delta", aggfunc="sum", fill_value=0)
        .reindex(columns=names, fill_value=0)
        .cumsum()
    )
    table.columns.name = None
    return table.astype("int64")


def read_fcd(path: str | os.PathLike[str], step: float | None = None, fallback_step: float = 1.0) -> pd.DataFrame:
    """SUMO's FCD output as columns ``t`` (sbsim time: FCD time + step), ``vehicle``, ``x``, ``y``, ``speed``.

    ``step`` defaults to the spacing of the FCD's time steps (``fallback_step`` if it has only one)."""
    rows: list[tuple[float, str, float, float, float]] = []
    try:
        for step_record, vehicle in sumolib.xml.parse_fast_nested(
            os.fspath(path), "timestep", ["time"], "vehicle", ["id", "x", "y", "speed"]
        ):
            rows.append((float(step_record.time), vehicle.id, float(vehicle.x), float(vehicle.y), float(vehicle.speed)))
    except OSError as e:
        raise ReportError(f"{path}: {e.strerror or e}") from e
    except UnicodeDecodeError as e:
        raise ReportError(f"{path}: not UTF-8 text") from e
    except ValueError as e:
        raise ReportError(f"{path}: a vehicle state is not numeric ({e})") from e
    if not rows and not _looks_like_fcd(path):
        raise ReportError(f"{path}: not SUMO FCD output (no <fcd-export>)")
    frame = pd.DataFrame(rows, columns=["t", "vehicle", "x", "y", "speed"])
    if step is None:
        spacing = frame["t"].drop_duplicates().sort_values().diff().dropna()
        step = float(spacing[spacing > 0].min()) if (spacing > 0).any() else fallback_step
    frame["t"] = (frame["t"] + step).round(3)
    return frame


def _looks_like_fcd(path: str | os.PathLike[str]) -> bool:
    with open(path, "rb") as f:
        return b"<fcd-export" in f.read(1 << 16)


@dataclass(frozen=True)
class Scenario:
    """What the report reads from a sumocfg: its net file and step length."""

    sumocfg: Path
    net_file: Path
    step_length: float | None


def read_sumocfg(path: str | os.PathLike[str]) -> Scenario:
    """The sumocfg's ``net-file`` (relative to the sumocfg) and ``step-length`` (None if not set)."""
    path = Path(path)
    # sax would take a missing path for a URL and fail with a confusing message.
    if not path.is_file():
        raise ReportError(f"{path}: No such file" if not path.exists() else f"{path}: not a file")
    try:
        options = {o.name: o.value for o in sumolib.options.readOptions(os.fspath(path))}
    except OSError as e:
        raise ReportError(f"{path}: {e.strerror or e}") from e
    except xml.sax.SAXParseException as e:
        raise ReportError(f"{path}:{e.getLineNumber()}: bad XML: {e.getMessage()}") from e
    except (xml.sax.SAXException, UnicodeDecodeError) as e:
        raise ReportError(f"{path}: bad XML: {e}") from e
    net = options.get("net-file", "").split(",")[0].strip()
    if not net:
        raise ReportError(f"{path}: names no net-file")
    try:
        step = float(options["step-length"]) if "step-length" in options else None
    except ValueError as e:
        raise ReportError(f"{path}: step-length is not a number") from e
    return Scenario(path, path.parent / net, step)


def read_net(path: str | os.PathLike[str]) -> sumolib.net.Net:
    """The SUMO network (sumolib), with errors as :class:`ReportError` naming the file."""
    if not Path(path).is_file():
        raise ReportError(f"{path}: no such net file" if not Path(path).exists() else f"{path}: not a file")
    try:
        return sumolib.net.readNet(os.fspath(path))
    except OSError as e:
        raise ReportError(f"{path}: {e.strerror or e}") from e
    except xml.sax.SAXParseException as e:
        raise ReportError(f"{path}:{e.getLineNumber()}: bad XML: {e.getMessage()}") from e
    except (xml.sax.SAXException, UnicodeDecodeError, ValueError, KeyError) as e:
        raise ReportError(f"{path}: not a SUMO network ({e})") from e


def load_summary(path: str | os.PathLike[str]) -> dict[str, Any]:
    try:
        data = read_summary(path)
    except OSError as e:
        raise ReportError(f"{path}: {e.strerror or e}") from e
    except json.JSONDecodeError as e:
        raise ReportError(f"{path}:{e.lineno}: bad JSON: {e.msg}") from e
    except UnicodeDecodeError as e:
        raise ReportError(f"{path}: not UTF-8 text") from e
    if not isinstance(data, dict):
        raise ReportError(f"{path}: not an sbsim summary (not a JSON object)")
    return data


def load_events(path: str | os.PathLike[str]) -> list[dict[str, Any]]:
    try:
        return read_events(path)
    except EventLogError as e:
        raise ReportError(str(e)) from e
    except OSError as e:
        raise ReportError(f"{path}: {e.strerror or e}") from e
    except UnicodeDecodeError as e:
        raise ReportError(f"{path}: not UTF-8 text") from e


@dataclass(frozen=True)
class Area:
    """One area of a story, in SUMO's frame, as ``sbsim check --json`` reports it: a polygon's vertices
    (not closed), or with ``radius`` a circle around ``points[0]``."""

    story: str
    condition: str
    points: tuple[tuple[float, float], ...]
    radius: float | None = None


#: How long ``sbsim check`` may take (it loads SUMO's network and the script, and runs nothing).
CHECK_TIMEOUT_S = 300.0


def story_areas(
    story: str | os.PathLike[str], sumocfg: str | os.PathLike[str], params: Sequence[str] = ()
) -> dict[str, list[Area]]:
    """Each story of the script (in registration order) with its areas, from ``sbsim check --json``.

    ``params`` are ``NAME=VALUE`` strings passed as ``--param`` (a script may place its areas by
    them). Raises :class:`ReportError` when sbsim is missing or rejects the script or scenario."""
    extra = [arg for param in params for arg in ("--param", param)]
    try:
        done = runner.run(sumocfg, story=story, extra=[*extra, "check", "--json"], timeout=CHECK_TIMEOUT_S)
    except OSError as e:  # no sbsim found (runner.executable), or one that does not start
        raise ReportError(f"{e.filename or 'sbsim'}: {e.strerror or e}") from e
    except subprocess.TimeoutExpired as e:
        raise ReportError(f"{story}: sbsim check took more than {CHECK_TIMEOUT_S:g} s") from e
    # 1 would be warnings under --strict, which is not asked for: anything but 0 is a failure.
    if done.returncode != 0:
        raise ReportError(f"{story}: sbsim check failed (exit {done.returncode}): {_check_error(done.stderr)}")
    try:
        document = json.loads(done.stdout)
        return {
            entry["name"]: [
                Area(
                    entry["name"],
                    area["condition"],
                    tuple((float(x), float(y)) for x, y in area["points"]),
                    float(area["radius"]) if "radius" in area else None,
                )
                for area in entry["areas"]
            ]
            for entry in document["stories"]
        }
    except (json.JSONDecodeError, KeyError, TypeError, ValueError) as e:
        raise ReportError(f"{story}: sbsim check --json printed no story areas ({e!r}); is sbsim older?") from e


def _check_error(stderr: str) -> str:
    """The line of sbsim's stderr that says what is wrong: its last own ``sbsim: ...`` line (a script's
    error comes after Python's traceback), else the last line."""
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    own = [line.removeprefix("sbsim: ") for line in lines if line.startswith("sbsim: ")]
    return own[-1] if own else lines[-1] if lines else "no message"


# ---------------------------------------------------------------------------------------------------------------------
# Figures


#: Map markers, one per story in turn.
MARKERS = ("o", "x", "^", "+", "s", "v", "D", "*")


def _color(index: int) -> str:
    return f"C{index % 10}"


def plot_activity(events: Events, end: float | None = None, names: Sequence[str] | None = None) -> Figure:
    """Vehicles under each story over time, stacked and step-wise.

    One :class:`matplotlib.patches.StepPatch` per story (labelled with its name) on the single axes:
    ``values - baseline`` over ``edges`` is that story's count. The last step lasts until ``end``
    (default: one second after the last change)."""
    frame = events_frame(events)
    names = list(names) if names is not None else stories(frame)
    counts = active_counts(frame, names)
    fig = Figure(figsize=(9, 4), layout="constrained")
    ax = fig.add_subplot()
    ax.set_xlabel("time [s]")
    ax.set_ylabel("vehicles under the story")
    ax.set_title("Vehicles under each story (stacked)")
    if counts.empty:
        ax.text(0.5, 0.5, "no activations", ha="center", va="center", transform=ax.transAxes)
        return fig
    times = counts.index.to_list()
    last = times[-1] + 1.0 if end is None or end <= times[-1] else end
    edges = [*times, last]
    bottom = pd.Series(0, index=counts.index)
    for i, name in enumerate(names):
        top = bottom + counts[name]
        ax.stairs(top.to_numpy(), edges, baseline=bottom.to_numpy(), fill=True, label=name, color=_color(i))
        bottom = top
    ax.set_xlim(min(0.0, times[0]), last)
    ax.set_ylim(bottom=0)
    ax.legend(loc="upper right")
    return fig


def plot_durations(events: Events, names: Sequence[str] | None = None) -> Figure:
    """How long vehicles stayed under each story: one histogram of completed stays per story, each axes
    labelled with its story (``Axes.get_label()``)."""
    frame = events_frame(events)
    names = list(names) if names is not None else stories(frame)
    table = stays(frame)
    shown = names or ["(no stories)"]
    columns = min(3, len(shown))
    rows = math.ceil(len(shown) / columns)
    fig = Figure(figsize=(4 * columns, 3.2 * rows), layout="constrained")
    axes = fig.subplots(rows, columns, squeeze=False).ravel()
    for ax in axes[len(shown) :]:
        ax.set_visible(False)
    for i, (ax, name) in enumerate(zip(axes, shown, strict=False)):
        ax.set_label(name)
        mine = table[table["story"] == name]
        done = mine["duration"].dropna()
        still = len(mine) - len(done)
        title = f"{name}: {len(done)} stays"
        if len(done):
            title += f", mean {done.mean():.1f} s"
            ax.hist(done.to_numpy(), bins=min(30, max(1, done.nunique())), color=_color(i))
        else:
            ax.text(0.5, 0.5, "no completed stay", ha="center", va="center", transform=ax.transAxes)
        if still:
            title += f"\n({still} still active at the end, not counted)"
        ax.set_title(title, fontsize="medium")
        ax.set_xlabel("time under the story [s]")
        ax.set_ylabel("stays")
    return fig


def activation_positions(events: Events, fcd: pd.DataFrame) -> pd.DataFrame:
    """Each activation with where its vehicle was (``x``, ``y`` from the FCD at the activation time);
    activations the FCD has no state for are left out."""
    table = stays(events)
    where = fcd[["t", "vehicle", "x", "y"]].rename(columns={"t": "start"})
    return table.merge(where, on=["vehicle", "start"], how="inner")


def plot_map(
    net: sumolib.net.Net,
    events: Events,
    fcd: pd.DataFrame | None = None,
    names: Sequence[str] | None = None,
    areas: Mapping[str, Sequence[Area]] | None = None,
) -> Figure:
    """The network's lanes; each story's ``areas`` (:func:`story_areas`) as semi-transparent patches in
    its colour (a :class:`~matplotlib.patches.Polygon`, ``get_xy()`` closed, or a
    :class:`~matplotlib.patches.Circle`; the first of a story labelled with its name); and, with the
    FCD, where each story activated: one scatter per story, labelled ``<name> (<count>)``
    (``get_offsets()`` are the SUMO x, y of its activations)."""
    frame = events_frame(events)
    names = list(names) if names is not None else stories(frame)
    areas = areas or {}
    # Stories that never activated still have their areas drawn (and a colour of their own).
    names += [name for name in areas if name not in names]
    fig = Figure(figsize=(8, 8), layout="constrained")
    ax = fig.add_subplot()
    shapes = [lane.getShape() for edge in net.getEdges() for lane in edge.getLanes()]
    ax.add_collection(LineCollection(shapes, colors="0.7", linewidths=0.8, label="lanes"))
    (xmin, ymin), (xmax, ymax) = net.getBBoxXY()
    margin = 0.03 * max(xmax - xmin, ymax - ymin, 1.0)
    ax.set_xlim(xmin - margin, xmax + margin)
    ax.set_ylim(ymin - margin, ymax + margin)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    for i, name in enumerate(names):
        for k, area in enumerate(areas.get(name, ())):
            ax.add_patch(_area_patch(area, _color(i), label=name if k == 0 else "_nolegend_"))
    drawn_areas = any(areas.values())
    if fcd is None:
        ax.set_title(
            f"Network{' and the stories’ areas' if drawn_areas else ''} (pass --fcd to see where stories activated)"
        )
        if drawn_areas:
            ax.legend(loc="upper right")
        return fig
    ax.set_title(f"{'The stories’ areas and w' if drawn_areas else 'W'}here vehicles were when each story activated")
    points = activation_positions(frame, fcd)
    for i, name in enumerate(names):
        mine = points[points["story"] == name]
        # Stories often share places (one condition inside another): distinct markers keep both visible.
        marker = MARKERS[i % len(MARKERS)]
        ax.scatter(mine["x"], mine["y"], s=18, marker=marker, color=_color(i), alpha=0.8, label=f"{name} ({len(mine)})")
    if names:
        ax.legend(loc="upper right")
    return fig


def _area_patch(area: Area, color: str, label: str) -> Polygon | Circle:
    # Filled lightly so lanes and activation points stay visible through it; the outline shows the edge.
    style = {"facecolor": to_rgba(color, 0.25), "edgecolor": to_rgba(color, 0.9), "linewidth": 1.2, "label": label}
    if area.radius is not None:
        return Circle(area.points[0], area.radius, **style)
    return Polygon(area.points, closed=True, **style)


def speeds_by_story(events: Events, fcd: pd.DataFrame, story: str) -> pd.DataFrame:
    """Mean speed per time step of the running vehicles under ``story`` and of the others: indexed by
    time, columns ``under`` and ``others`` (NaN where a group is empty)."""
    table = stays(events)
    mine = table[table["story"] == story][["vehicle", "start", "end"]]
    rows = fcd[["t", "vehicle"]].reset_index().merge(mine, on="vehicle")
    # Active from its activation's evaluation up to (not including) its deactivation's.
    inside = rows[(rows["t"] >= rows["start"]) & (rows["t"] < rows["end"].fillna(math.inf))]
    under = fcd.index.isin(inside["index"])
    means = fcd.groupby([pd.Series(under, index=fcd.index, name="under"), "t"])["speed"].mean()
    out = pd.DataFrame(index=pd.Index(sorted(fcd["t"].unique()), name="t"))
    out["under"] = means.get(True, pd.Series(dtype="float64")).reindex(out.index)
    out["others"] = means.get(False, pd.Series(dtype="float64")).reindex(out.index)
    return out


def plot_speeds(events: Events, fcd: pd.DataFrame, names: Sequence[str] | None = None) -> Figure:
    """Per story (one axes each, labelled with its name), the mean speed over time of the vehicles under
    it (line labelled ``under <story>``) and of the other running vehicles (``others``)."""
    frame = events_frame(events)
    names = list(names) if names is not None else stories(frame)
    shown = names or ["(no stories)"]
    fig = Figure(figsize=(9, 2.8 * len(shown)), layout="constrained")
    axes = fig.subplots(len(shown), 1, squeeze=False, sharex=True).ravel()
    for i, (ax, name) in enumerate(zip(axes, shown, strict=True)):
        ax.set_label(name)
        means = speeds_by_story(frame, fcd, name)
        ax.plot(means.index, means["under"], color=_color(i), label=f"under {name}")
        ax.plot(means.index, means["others"], color="0.4", linewidth=0.8, label="others")
        ax.set_title(f"{name}: mean speed", fontsize="medium")
        ax.set_ylabel("speed [m/s]")
        ax.legend(loc="upper right")
    axes[-1].set_xlabel("time [s]")
    return fig


# ---------------------------------------------------------------------------------------------------------------------
# Tables and the report


def story_table(
    events: Events, summary: dict[str, Any] | None = None, names: Sequence[str] | None = None
) -> pd.DataFrame:
    """Per story: activations, vehicles, completed stays, their mean duration, stays still open at the
    end; with the summary, its activation count and active vehicle-seconds beside them."""
    frame = events_frame(events)
    names = list(names) if names is not None else stories(frame, summary)
    table = stays(frame)
    rows = []
    for name in names:
        mine = table[table["story"] == name]
        done = mine["duration"].dropna()
        rows.append(
            {
                "story": name,
                "activations": len(mine),
                "vehicles": mine["vehicle"].nunique(),
                "completed stays": len(done),
                "mean duration [s]": done.mean() if len(done) else math.nan,
                "active at the end": len(mine) - len(done),
            }
        )
    out = pd.DataFrame(
        rows, columns=["story", "activations", "vehicles", "completed stays", "mean duration [s]", "active at the end"]
    ).set_index("story")
    if summary is not None:
        by_name = summary_stories(summary)
        out["activations (summary)"] = [by_name.get(n, {}).get("activations") for n in out.index]
        out["active vehicle-seconds (summary)"] = [by_name.get(n, {}).get("active_vehicle_seconds") for n in out.index]
    return out


#: Summary entries shown in the run table, in this order, with their labels.
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
    ("timing", "timing"),
)


def run_table(summary: dict[str, Any]) -> pd.DataFrame:
    """The summary's run-level figures (seed, end, steps, vehicles, messages, timing) as one column."""
    rows: dict[str, str] = {}
    for key, label in RUN_FIELDS:
        if key not in summary:
            continue
        value = summary[key]
        if key == "end" and isinstance(value, dict):
            rows[label] = f"{value.get('time')} s ({value.get('reason')})"
        elif isinstance(value, dict):
            rows[label] = ", ".join(f"{k}: {_short(v)}" for k, v in value.items()) or "none"
        else:
            rows[label] = str(value)
    return pd.DataFrame({"value": rows}).rename_axis("run")


def _short(value: Any) -> str:
    return f"{value:.3g}" if isinstance(value, float) else str(value)


@dataclass
class Report:
    """The figures (by name: ``activity``, ``durations``, ``map``, ``speeds`` with an FCD) and tables."""

    title: str
    figures: dict[str, Figure] = field(default_factory=dict)
    stories: pd.DataFrame = field(default_factory=pd.DataFrame)
    run: pd.DataFrame | None = None


def build(
    events: str | os.PathLike[str],
    sumocfg: str | os.PathLike[str],
    fcd: str | os.PathLike[str] | None = None,
    summary: str | os.PathLike[str] | None = None,
    story: str | os.PathLike[str] | None = None,
    params: Sequence[str] = (),
) -> Report:
    """Reads a run's files and draws its report; raises :class:`ReportError` for unusable input.

    With ``story`` (the run's script, and ``params`` its ``--param NAME=VALUE`` values) the map shows
    the stories' areas (:func:`story_areas`)."""
    log = load_events(events)
    scenario = read_sumocfg(sumocfg)
    net = read_net(scenario.net_file)
    data = load_summary(summary) if summary is not None else None
    trace = read_fcd(fcd, fallback_step=scenario.step_length or 1.0) if fcd is not None else None
    areas = story_areas(story, scenario.sumocfg, params) if story is not None else None
    frame = events_frame(log)
    names = stories(frame, data)
    names += [name for name in areas or {} if name not in names]
    ends = [float(frame["t"].max())] if len(frame) else []
    if data is not None and isinstance(data.get("end"), dict) and isinstance(data["end"].get("time"), int | float):
        ends.append(float(data["end"]["time"]))
    if trace is not None and len(trace):
        ends.append(float(trace["t"].max()))
    report = Report(title=f"sbsim report: {Path(events).name}")
    report.figures["activity"] = plot_activity(frame, max(ends) if ends else None, names)
    report.figures["durations"] = plot_durations(frame, names)
    report.figures["map"] = plot_map(net, frame, trace, names, areas)
    if trace is not None:
        report.figures["speeds"] = plot_speeds(frame, trace, names)
    report.stories = story_table(frame, data, names)
    report.run = run_table(data) if data is not None else None
    return report


def png(figure: Figure) -> bytes:
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=100)
    return buffer.getvalue()


def write_pngs(report: Report, directory: str | os.PathLike[str]) -> list[Path]:
    """Writes each figure as ``<name>.png`` into ``directory`` (created if missing)."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    out = []
    for name, figure in report.figures.items():
        path = directory / f"{name}.png"
        path.write_bytes(png(figure))
        out.append(path)
    return out


CAPTIONS = {
    "activity": "Vehicles under each story over time (stacked).",
    "durations": "How long vehicles stayed under each story (completed stays).",
    "map": "The network, the stories' areas (with --story) and where vehicles were when each story activated "
    "(from the FCD output).",
    "speeds": "Mean speed of the vehicles under each story against the other running vehicles.",
}


def to_html(report: Report) -> str:
    """One self-contained page: the tables and the figures as embedded PNGs."""
    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f"<title>{html.escape(report.title)}</title>",
        "<style>body{font-family:sans-serif;margin:2em;max-width:70em}"
        "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:.2em .6em;text-align:right}"
        "img{max-width:100%}figure{margin:1.5em 0}</style>",
        "</head><body>",
        f"<h1>{html.escape(report.title)}</h1>",
        "<h2>Stories</h2>",
        report.stories.to_html(classes="stories", float_format=lambda v: f"{v:.1f}", na_rep="-"),
    ]
    if report.run is not None:
        parts += ["<h2>Run</h2>", report.run.to_html(classes="run")]
    for name, figure in report.figures.items():
        data = base64.b64encode(png(figure)).decode("ascii")
        caption = html.escape(CAPTIONS.get(name, name))
        parts.append(
            f'<figure id="{name}"><img src="data:image/png;base64,{data}" alt="{caption}">'
            f"<figcaption>{caption}</figcaption></figure>"
        )
    parts.append("</body></html>")
    return "\n".join(parts) + "\n"


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog=PROG, description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("events", type=Path, help="the run's --events file (JSON Lines)")
    parser.add_argument("--sumocfg", type=Path, required=True, help="the run's SUMO configuration (for the net)")
    parser.add_argument("--story", type=Path, help="the run's story script: the map shows its areas (sbsim check)")
    parser.add_argument(
        "--param", action="append", default=[], metavar="NAME=VALUE", help="the run's --param values, for --story"
    )
    parser.add_argument("--fcd", type=Path, help="SUMO's FCD output of the run (positions and speeds)")
    parser.add_argument("--summary", type=Path, help="the run's --summary JSON")
    parser.add_argument("-o", "--output", type=Path, required=True, help="the HTML file to write")
    parser.add_argument("--png", type=Path, metavar="DIR", help="also write each figure as DIR/<name>.png")
    args = parser.parse_args(argv)
    try:
        report = build(
            args.events, args.sumocfg, fcd=args.fcd, summary=args.summary, story=args.story, params=args.param
        )
        page = to_html(report)
        try:
            args.output.write_text(page, encoding="utf-8")
        except OSError as e:
            raise ReportError(f"{args.output}: {e.strerror or e}") from e
        written = [args.output]
        if args.png is not None:
            try:
                written += write_pngs(report, args.png)
            except OSError as e:
                raise ReportError(f"{e.filename or args.png}: {e.strerror or e}") from e
    except ReportError as e:
        print(f"report: {e}", file=sys.stderr)
        return 2
    for path in written:
        print(f"report: wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
