"""Studies: one story run over parameter values x seeds, on Dask, with the results as two tables.

    python -m sbsim.study study.toml [--scheduler tcp://host:8786] [--workers N] [--plot] [--fail-on-criteria]

The TOML names the scenario, the seeds and the parameter values (paths relative to the TOML)::

    sumocfg = "grid-rain.sumocfg"
    story = "story.py"                  # optional; also: services = "services.xml", radio = "radio.toml"
    plugins = ["build/libmine.so"]      # optional: each run's --plugin
    seeds = { first = 1, count = 10 }   # or a list: seeds = [1, 2, 3]
    end = 600                           # optional
    args = ["--threads", "1", "--", "--fcd-output", "{run_dir}/fcd.xml"]   # optional: more sbsim words
    [parameters]
    rain_speed = [5, 10, 15]
    [outputs]
    directory = "results/rain"
    messages = false                    # true: every run's --messages trace (Parquet), and messages/
    statistics = false                  # true: every run's --statistics file, and statistics.parquet

Each run is one ``sbsim`` process (crash isolation; SUMO is not re-entrant) started by a Dask task,
on a ``distributed.LocalCluster`` with one single-threaded worker process per core, or on an
existing cluster (``--scheduler``; workers must see the same file system). Every run works in its
own folder ``runs/<id>/`` (``seed-<n>`` without parameters): events.jsonl, summary.json, stderr.txt,
result.json (written last), and whatever the run writes there: ``{run_dir}`` in ``args`` and in
parameter values is that folder (absolute; ``{{``/``}}`` are braces), and relative outputs land in it.
A word of ``args`` (or the value of ``--option=value``) naming an existing file relative to the TOML
is made absolute; other words are passed as written. A run whose folder still holds what it wrote
(result.json says it succeeded, its outputs have the sizes recorded, no ``*.incomplete``) is not run
again, so an interrupted study resumes where it stopped; SIGINT (Ctrl-C) or SIGTERM stops the runs
under way and exits with 130. At the end ``runs.parquet`` (one row per run) and ``events.parquet``
(every event with its run's parameters and seed) are written beside them, and with ``messages = true``
``messages/`` (the runs' Parquet message traces as one dataset partitioned by ``run``: join with
runs.parquet for parameters and seed; read it with :func:`sbsim.messages.read_messages`), with ``statistics = true``
``statistics.parquet`` (every value the runs recorded, likewise). ``junit.xml`` holds one test suite per
run, named by its parameters and seed (``rain_speed=5, seed=1``), with a test case per criterion (a failed
run: one ``run`` case with an error); ``--fail-on-criteria`` makes the study's exit code 3 when all runs
completed but a criterion of one failed (0 without it; 1 when a run failed stays 1).

The package, one job a module: :mod:`~sbsim.study.spec` (the TOML file and its runs),
:mod:`~sbsim.study.execution` (the runs on Dask), :mod:`~sbsim.study.tables` (Parquet tables and
plots), :mod:`~sbsim.study.junit` (the JUnit file) and :mod:`~sbsim.study.cli`; a run's summary becomes its row through
:func:`sbsim.summary.table_columns`.
"""

from __future__ import annotations

from sbsim.study.cli import main
from sbsim.study.execution import STDERR_TAIL, StudyInterrupted, StudyResult, execute, result_of, run, stop_runs
from sbsim.study.junit import suite_name, write_junit, xml_text
from sbsim.study.spec import Run, StudyError, StudySpec, Value
from sbsim.study.tables import plot, write_tables

__all__ = [
    "STDERR_TAIL",
    "Run",
    "StudyError",
    "StudyInterrupted",
    "StudyResult",
    "StudySpec",
    "Value",
    "execute",
    "main",
    "plot",
    "result_of",
    "run",
    "stop_runs",
    "suite_name",
    "write_junit",
    "write_tables",
    "xml_text",
]
