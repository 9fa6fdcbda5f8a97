"""The report's figures, each a :class:`matplotlib.figure.Figure` (drawn off-screen, no pyplot state).

1. :func:`plot_activity`: vehicles under each story over time, stacked and step-wise, from the
   activate / deactivate events;
2. :func:`plot_durations`: how long each stay under a story lasted (one histogram per story; stays
   still open when the log ends have no length and are only counted in the title);
3. :func:`plot_map`: the network's lanes, each story's areas (:mod:`sbsim.report.areas`), and where
   vehicles were when each story activated (from the FCD);
4. :func:`plot_speeds`: mean speed per time step of the vehicles under each story against the other
   running vehicles (from the FCD).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import pandas as pd
import sumolib
from matplotlib.collections import LineCollection
from matplotlib.colors import to_rgba
from matplotlib.figure import Figure
from matplotlib.patches import Circle, Polygon

from sbsim.report.analysis import (
    Events,
    activation_positions,
    active_counts,
    events_frame,
    speeds_by_story,
    stays,
    stories,
    world_stories,
)
from sbsim.report.areas import Area

#: Map markers, one per story in turn.
MARKERS = ("o", "x", "^", "+", "s", "v", "D", "*")


def _color(index: int) -> str:
    return f"C{index % 10}"


def plot_activity(events: Events, end: float | None = None, names: Sequence[str] | None = None) -> Figure:
    """Vehicles under each story over time, stacked and step-wise.

    One :class:`matplotlib.patches.StepPatch` per vehicle story (labelled with its name) on the single
    axes: ``values - baseline`` over ``edges`` is that story's count. The last step lasts until ``end``
    (default: one second after the last change). A world story counts no vehicles: each period it was
    active is a hatched span (the first labelled ``<name> (world story, active)``)."""
    frame = events_frame(events)
    names = list(names) if names is not None else stories(frame)
    world = set(world_stories(frame))
    counts = active_counts(frame, [n for n in names if n not in world])
    fig = Figure(figsize=(9, 4), layout="constrained")
    ax = fig.add_subplot()
    ax.set_xlabel("time [s]")
    ax.set_ylabel("vehicles under the story")
    ax.set_title("Vehicles under each story (stacked)" + ("; world stories shaded while active" if world else ""))
    periods = stays(frame)
    periods = periods[periods["story"].isin(world)]
    if counts.empty and periods.empty:
        ax.text(0.5, 0.5, "no activations", ha="center", va="center", transform=ax.transAxes)
        return fig
    times = sorted({*counts.index.to_list(), *periods["start"].to_list(), *periods["end"].dropna().to_list()})
    last = times[-1] + 1.0 if end is None or end <= times[-1] else end
    # A world story has no vehicles to count: its active periods are spans behind the counts.
    for i, name in enumerate(names):
        if name not in world:
            continue
        for k, (_, row) in enumerate(periods[periods["story"] == name].iterrows()):
            stop = last if math.isnan(row["end"]) else row["end"]
            label = f"{name} (world story, active)" if k == 0 else "_nolegend_"
            ax.axvspan(row["start"], stop, color=_color(i), alpha=0.2, hatch="//", label=label)
    if not counts.empty:
        edges = [*counts.index.to_list(), last]
        bottom = pd.Series(0, index=counts.index)
        for i, name in enumerate(names):
            if name in world:
                continue
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
    FCD, where each vehicle story activated: one scatter per story, labelled ``<name> (<count>)``
    (``get_offsets()`` are the SUMO x, y of its activations); world stories have no such place."""
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
    world = set(world_stories(frame))
    for i, name in enumerate(names):
        if name in world:
            continue  # about the network: no vehicle, no place it activated at
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


def plot_speeds(events: Events, fcd: pd.DataFrame, names: Sequence[str] | None = None) -> Figure:
    """Per story (one axes each, labelled with its name), the mean speed over time of the vehicles under
    it (line labelled ``under <story>``) and of the other running vehicles (``others``). World stories
    have no vehicles under them, so no axes."""
    frame = events_frame(events)
    names = list(names) if names is not None else stories(frame)
    world = set(world_stories(frame))
    shown = [name for name in names if name not in world] or ["(no vehicle stories)"]
    fig = Figure(figsize=(9, 2.8 * len(shown)), layout="constrained")
    axes = fig.subplots(len(shown), 1, squeeze=False, sharex=True).ravel()
    for ax, name in zip(axes, shown, strict=True):
        ax.set_label(name)
        means = speeds_by_story(frame, fcd, name)
        # The story's colour in every figure: its place among all the stories, world ones too.
        i = names.index(name) if name in names else 0
        ax.plot(means.index, means["under"], color=_color(i), label=f"under {name}")
        ax.plot(means.index, means["others"], color="0.4", linewidth=0.8, label="others")
        ax.set_title(f"{name}: mean speed", fontsize="medium")
        ax.set_ylabel("speed [m/s]")
        ax.legend(loc="upper right")
    axes[-1].set_xlabel("time [s]")
    return fig
