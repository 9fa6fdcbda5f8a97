"""A report put together: one run's files read, analysed and drawn."""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd
from matplotlib.figure import Figure

from sbsim.report.analysis import events_frame, stories
from sbsim.report.areas import story_areas
from sbsim.report.figures import plot_activity, plot_durations, plot_map, plot_speeds
from sbsim.report.loading import load_events, load_fcd, load_messages, load_summary, read_net, read_sumocfg
from sbsim.report.tables import run_table, story_table
from sbsim.report.v2x import speeds_by_denm
from sbsim.report.v2x_figures import plot_busy_ratio, plot_delivery, plot_denm_speeds, plot_messages
from sbsim.summary import end_time


@dataclass
class Report:
    """The figures (by name: ``activity``, ``durations``, ``map``, ``speeds`` with an FCD; with a message
    trace ``messages``, ``delivery``, ``busy_ratio`` and, with an FCD too, ``denm_speeds``) and tables (``v2x``:
    the V2X panels' data by the same names)."""

    title: str
    figures: dict[str, Figure] = field(default_factory=dict)
    stories: pd.DataFrame = field(default_factory=pd.DataFrame)
    run: pd.DataFrame | None = None
    v2x: dict[str, pd.DataFrame] = field(default_factory=dict)


def build(
    events: str | os.PathLike[str],
    sumocfg: str | os.PathLike[str],
    fcd: str | os.PathLike[str] | None = None,
    summary: str | os.PathLike[str] | None = None,
    story: str | os.PathLike[str] | None = None,
    params: Sequence[str] = (),
    messages: str | os.PathLike[str] | None = None,
) -> Report:
    """Reads a run's files and draws its report; raises :class:`~sbsim.report.loading.ReportError` for
    unusable input.

    With ``story`` (the run's script, and ``params`` its ``--param NAME=VALUE`` values) the map shows
    the stories' areas (:func:`~sbsim.report.areas.story_areas`); with ``messages`` (the run's ``--messages``
    trace) the V2X panels (:mod:`sbsim.report.v2x`)."""
    log = load_events(events)
    scenario = read_sumocfg(sumocfg)
    net = read_net(scenario.net_file)
    data = load_summary(summary) if summary is not None else None
    trace = load_fcd(fcd, fallback_step=scenario.step_length or 1.0) if fcd is not None else None
    areas = story_areas(story, scenario.sumocfg, params) if story is not None else None
    frame = events_frame(log)
    names = stories(frame, data)
    names += [name for name in areas or {} if name not in names]
    ends = [float(frame["t"].max())] if len(frame) else []
    if (ended := end_time(data)) is not None:
        ends.append(ended)
    if trace is not None and len(trace):
        ends.append(float(trace["t"].max()))
    report = Report(title=f"sbsim report: {Path(events).name}")
    report.figures["activity"] = plot_activity(frame, max(ends) if ends else None, names)
    report.figures["durations"] = plot_durations(frame, names)
    report.figures["map"] = plot_map(net, frame, trace, names, areas)
    if trace is not None:
        report.figures["speeds"] = plot_speeds(frame, trace, names)
    if messages is not None:
        tables = load_messages(messages)
        report.v2x["messages"] = tables.messages_per_type()
        report.v2x["delivery"] = tables.delivery_by_distance()
        report.v2x["busy_ratio"] = tables.busy_ratio_over_time()
        report.figures["messages"] = plot_messages(report.v2x["messages"])
        report.figures["delivery"] = plot_delivery(report.v2x["delivery"])
        report.figures["busy_ratio"] = plot_busy_ratio(report.v2x["busy_ratio"])
        if trace is not None:
            report.v2x["denm_speeds"] = speeds_by_denm(tables, trace)
            report.figures["denm_speeds"] = plot_denm_speeds(report.v2x["denm_speeds"])
    report.stories = story_table(frame, data, names)
    report.run = run_table(data) if data is not None else None
    return report
