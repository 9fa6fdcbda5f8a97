"""Watching a story: what one run's stories did, as figures and a table in one HTML file.

    python -m sbsim.report events.jsonl --sumocfg C [--story S [--param N=V]] [--fcd f.xml] [--summary s.json]
        [--messages m.jsonl] -o report.html [--png DIR]

Figures (also as functions returning :class:`matplotlib.figure.Figure`, :mod:`sbsim.report.figures`):

1. :func:`plot_activity`: vehicles under each story over time, stacked and step-wise, from the
   activate / deactivate events;
2. :func:`plot_durations`: how long each stay under a story lasted (one histogram per story; stays
   still open when the log ends have no length and are only counted in the title);
3. :func:`plot_map`: the network's lanes (the sumocfg's ``net-file``, read with sumolib), with
   ``--story`` each story's areas, and where vehicles were when each story activated for them;
4. :func:`plot_speeds` (needs ``--fcd``): mean speed per time step of the vehicles under each story
   against the other running vehicles (world stories, which have no vehicles, have none).

With the run's message trace (``--messages``), the V2X panels (:mod:`sbsim.report.v2x_figures`, their
tables in :mod:`sbsim.report.v2x` and ``Report.v2x``): messages sent per type over time, packet
delivery ratio against distance (50 m bins, per type; also a table on the page), the channel busy
ratio over time (the 802.11p channel model's, ``--radio``), and with ``--fcd`` the mean speed of the
vehicles that had received a DENM against the others.

Where stories act: the event log and the summary carry neither the stories' areas nor positions
(an event is ``t``, ``type``, ``story``, ``vehicle``). The areas live in the story script, which
needs sbsim's compiled module to load, so with ``--story`` (and the run's ``--param`` values, if the
script reads them) the report runs ``sbsim check --json`` (the executable
:func:`sbsim.runner.executable` finds) and draws every ``PolygonCondition`` as a filled polygon
and every ``DistanceCondition`` around a point as a circle, in the story's colour and in SUMO's
frame whatever frame the script used (:func:`story_areas`). The activation positions are what the
run itself recorded: read from SUMO's FCD output (``--sumo-option "--fcd-output f.xml"``) at the
activation time (:mod:`sbsim.fcd` puts its times in sbsim's). Without ``--story`` and ``--fcd`` the
map shows the network only.

Bad input (a missing or unreadable file, a line of the log that is not an event, a broken sumocfg,
net, FCD or summary, a story script ``sbsim check`` rejects) is one line on stderr naming the file,
and exit code 2.

The package, one job a module: :mod:`~sbsim.report.loading` (the run's files, errors as
:class:`ReportError`), :mod:`~sbsim.report.areas` (``sbsim check``), :mod:`~sbsim.report.analysis`
(stays and counts from the log), :mod:`~sbsim.report.tables`, :mod:`~sbsim.report.figures`,
:mod:`~sbsim.report.compose` (:func:`build`), :mod:`~sbsim.report.html` and :mod:`~sbsim.report.cli`.
"""

from __future__ import annotations

import sys

from sbsim.extras import missing_message

# Checked before the modules below import them. `python -m sbsim.report` imports this package first,
# while sys.argv[0] is still "-m" (Python's documented behaviour): the command gets one line and
# exit code 2, a program importing the package an ImportError saying the same.
_missing = missing_message("report", ("pandas", "matplotlib", "sumolib"))
if _missing is not None:
    if sys.argv[:1] == ["-m"]:
        print(_missing, file=sys.stderr)
        sys.exit(2)
    raise ModuleNotFoundError(_missing)

from sbsim.fcd import read_fcd  # noqa: E402
from sbsim.report.analysis import (  # noqa: E402
    Events,
    activation_positions,
    active_counts,
    events_frame,
    speeds_by_story,
    stays,
    stories,
)
from sbsim.report.areas import CHECK_TIMEOUT_S, Area, story_areas  # noqa: E402
from sbsim.report.cli import PROG, main  # noqa: E402
from sbsim.report.compose import Report, build  # noqa: E402
from sbsim.report.figures import MARKERS, plot_activity, plot_durations, plot_map, plot_speeds  # noqa: E402
from sbsim.report.html import CAPTIONS, png, to_html, write_pngs  # noqa: E402
from sbsim.report.loading import ReportError, Scenario, load_events, load_fcd, load_summary, read_net, read_sumocfg  # noqa: E402
from sbsim.report.tables import run_table, story_table  # noqa: E402

__all__ = [
    "CAPTIONS",
    "CHECK_TIMEOUT_S",
    "MARKERS",
    "PROG",
    "Area",
    "Events",
    "Report",
    "ReportError",
    "Scenario",
    "activation_positions",
    "active_counts",
    "build",
    "events_frame",
    "load_events",
    "load_fcd",
    "load_summary",
    "main",
    "plot_activity",
    "plot_durations",
    "plot_map",
    "plot_speeds",
    "png",
    "read_fcd",
    "read_net",
    "read_sumocfg",
    "run_table",
    "speeds_by_story",
    "stays",
    "stories",
    "story_areas",
    "story_table",
    "to_html",
    "write_pngs",
]
