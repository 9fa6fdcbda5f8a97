"""The report's V2X panels (with a message trace), each a :class:`matplotlib.figure.Figure` drawn from the
tables of :mod:`sbsim.report.v2x`:

1. :func:`plot_messages`: transmissions per message type per second;
2. :func:`plot_delivery`: packet delivery ratio against distance, per message type, 50 m bins;
3. :func:`plot_busy_ratio`: the channel busy ratio over time (mean and max per second);
4. :func:`plot_denm_speeds` (needs the FCD): mean speed of DENM receivers against the others.
"""

from __future__ import annotations

import pandas as pd
from matplotlib.figure import Figure


def _empty(ax: object, text: str) -> None:
    ax.text(0.5, 0.5, text, ha="center", va="center", transform=ax.transAxes)  # type: ignore[attr-defined]


def plot_messages(per_type: pd.DataFrame, bin_seconds: float = 1.0) -> Figure:
    """One axes per message type (labelled with it, each its own scale: a few DENMs beside hundreds of CAMs),
    its transmissions in each bin of :func:`~sbsim.report.v2x.messages_per_type` as stairs."""
    kinds = list(per_type.columns) or ["(no messages)"]
    fig = Figure(figsize=(9, 1.2 + 2.2 * len(kinds)), layout="constrained")
    axes = fig.subplots(len(kinds), 1, squeeze=False, sharex=True).ravel()
    fig.suptitle("Messages sent per type")
    for i, (ax, kind) in enumerate(zip(axes, kinds, strict=True)):
        ax.set_label(str(kind))
        ax.set_ylabel(f"{kind} per {bin_seconds:g} s")
        if per_type.empty:
            _empty(ax, "no transmissions")
            continue
        edges = [*per_type.index, per_type.index[-1] + bin_seconds]
        ax.stairs(per_type[kind].to_numpy(), edges, color=f"C{i % 10}", label=str(kind))
        ax.set_ylim(bottom=0)
    axes[-1].set_xlabel("time [s]")
    return fig


def plot_delivery(delivery: pd.DataFrame) -> Figure:
    """Per message type (a line labelled with it, markers at the bins' centres): the delivery ratio of
    :func:`~sbsim.report.v2x.delivery_by_distance`."""
    fig = Figure(figsize=(9, 3.5), layout="constrained")
    ax = fig.add_subplot()
    ax.set_title("Packet delivery ratio against distance")
    ax.set_xlabel("distance sender-receiver [m]")
    ax.set_ylabel("delivery ratio")
    ax.set_ylim(-0.02, 1.02)
    if delivery.empty:
        _empty(ax, "no receptions and losses in the trace (trace lost receptions: --messages-events tx,rx,lost,denm)")
        return fig
    width = float(delivery["distance"].diff().where(lambda d: d > 0).min() or 50.0)
    for i, (kind, rows) in enumerate(delivery.groupby("type", sort=True)):
        ax.plot(rows["distance"] + width / 2, rows["pdr"], marker="o", color=f"C{i % 10}", label=str(kind))
    ax.legend(loc="lower left")
    return fig


def plot_busy_ratio(busy: pd.DataFrame) -> Figure:
    """The mean (line labelled ``mean``) and max (``max``) channel busy ratio per bin of
    :func:`~sbsim.report.v2x.busy_ratio_over_time`."""
    fig = Figure(figsize=(9, 3), layout="constrained")
    ax = fig.add_subplot()
    ax.set_title("Channel busy ratio (as the senders measured it)")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("channel busy ratio")
    if busy.empty:
        _empty(ax, "no channel busy ratio in the trace (the disc model has none: run with --radio)")
        return fig
    ax.plot(busy.index, busy["mean"], color="C0", label="mean")
    ax.plot(busy.index, busy["max"], color="C3", linewidth=0.8, label="max")
    ax.set_ylim(bottom=0)
    ax.legend(loc="upper right")
    return fig


def plot_denm_speeds(speeds: pd.DataFrame) -> Figure:
    """Mean speed of the vehicles that had received a DENM (line ``warned (DENM received)``) and of the
    others (``others``), from :func:`~sbsim.report.v2x.speeds_by_denm`."""
    fig = Figure(figsize=(9, 3.5), layout="constrained")
    ax = fig.add_subplot()
    ax.set_title("Mean speed: vehicles that received a DENM against the others")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("speed [m/s]")
    if speeds["warned_n"].sum() == 0:
        _empty(ax, "no vehicle received a DENM")
    ax.plot(speeds.index, speeds["warned"], color="C3", label="warned (DENM received)")
    ax.plot(speeds.index, speeds["others"], color="0.4", linewidth=0.8, label="others")
    ax.legend(loc="upper right")
    return fig
