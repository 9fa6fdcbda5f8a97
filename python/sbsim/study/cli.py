"""The study's command line (``python -m sbsim.study``; the older ``python -m storyboard.study`` too)."""

from __future__ import annotations

import argparse
import json
import re
import signal
import sys
from collections.abc import Sequence
from pathlib import Path

from sbsim.extras import missing_message
from sbsim.runner import executable
from sbsim.study.execution import StudyInterrupted, check_radio, check_study, run
from sbsim.study.spec import StudyError, StudySpec
from sbsim.study.tables import plot, plot_column

#: What --scheduler accepts: Dask's protocol://host:port, or host:port.
SCHEDULER_ADDRESS = re.compile(r"((tcp|tls|ucx|inproc)://)?[\w.\-\[\]:]+:\d{1,5}")


def main(argv: Sequence[str] | None = None) -> int:
    """Runs the study; a bad study file is one line on stderr and exit code 2, a failed run exit code 1, and
    with --fail-on-criteria a run whose criterion failed exit code 3."""
    parser = argparse.ArgumentParser(
        prog="python -m sbsim.study",
        description=sys.modules["sbsim.study"].__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("study", type=Path, help="the study's TOML file")
    parser.add_argument("--scheduler", help="address of a running Dask scheduler (default: a local cluster)")
    parser.add_argument("--workers", type=int, help="local worker processes (default: one per core)")
    parser.add_argument("--timeout", type=float, help="seconds a single run may take (default: no limit)")
    parser.add_argument(
        "--plot",
        action="append",
        nargs="?",
        const="",
        metavar="COLUMN",
        help="also draw PNG files: alone, activations per story; with a runs.parquet column (stat:warned:mean), "
        "that column against the first parameter (repeatable)",
    )
    parser.add_argument(
        "--fail-on-criteria",
        action="store_true",
        help="exit with 3 when a run's criterion failed (all runs complete; junit.xml says which); default 0",
    )
    parser.add_argument(
        "--check",
        action="store_true",
        help="check the study file and every parameter combination with sbsim check; run nothing",
    )
    args = parser.parse_args(argv)
    # Before any run: the sweep (Dask), the tables (pandas, pyarrow), the progress bar and the plots.
    message = missing_message("study", ("dask", "distributed", "pandas", "pyarrow", "tqdm", "matplotlib"))
    if message is not None:
        print(message, file=sys.stderr)
        return 2
    if argv is None:  # the command: SIGINT and SIGTERM stop the study, even if started with SIGINT ignored (`&`)
        signal.signal(signal.SIGINT, signal.default_int_handler)
        signal.signal(signal.SIGTERM, signal.default_int_handler)
    try:
        spec = StudySpec.load(args.study)
        if args.workers is not None and args.workers < 1:
            raise StudyError("--workers must be >= 1")
        if args.timeout is not None and not args.timeout > 0:
            raise StudyError(f"--timeout must be > 0 seconds, not {args.timeout}")
        if args.scheduler is not None and not SCHEDULER_ADDRESS.fullmatch(args.scheduler):
            raise StudyError(f"--scheduler '{args.scheduler}' is not an address like tcp://host:8786")
        if args.check:
            total = check_study(spec, str(executable().resolve()))
            print(f"study: {args.study}: {total} runs, every parameter combination checked")
            return 0
        # Before anything is made: a mistake in the study file leaves no results folder behind.
        check_radio(spec, str(executable().resolve()))
        try:
            spec.directory.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise StudyError(f"the output folder '{spec.directory}' cannot be made: {e.strerror}") from e
        try:
            result = run(spec, scheduler=args.scheduler, workers=args.workers, timeout=args.timeout, check=False)
        except OSError as e:
            if args.scheduler is None:
                raise
            raise StudyError(f"--scheduler '{args.scheduler}': cannot reach it ({e})") from e
    except StudyError as e:
        print(f"study: {e}", file=sys.stderr)
        return 2
    except StudyInterrupted as e:
        print(
            f"study: interrupted: {e.finished} of {e.total} runs finished and kept in {spec.directory}; "
            f"run the same command again to do the other {e.total - e.finished}",
            file=sys.stderr,
        )
        return 130
    except KeyboardInterrupt:
        print("study: interrupted; finished runs are kept, run the same command again to go on", file=sys.stderr)
        return 130
    print(f"study: {len(result.rows)} runs ({result.ran} run now, {len(result.failed)} failed) in {spec.directory}")
    for row in result.failed_criteria:
        # Quoted as JSON: a name with a line break or a control character stays on its line.
        failed = [
            json.dumps(k.removeprefix("criterion:"), ensure_ascii=False)
            for k, v in row.items()
            if k.startswith("criterion:") and v is False
        ]
        print(f"study: run {row['run']}: criteria failed: {', '.join(failed)}", file=sys.stderr)
    for row in result.failed:
        print(f"study: run {row['run']} failed with exit code {row['exit_code']}", file=sys.stderr)
    for column in dict.fromkeys(args.plot or []):
        try:
            paths = [plot_column(spec.directory, spec, column)] if column else plot(spec.directory, spec)
        except StudyError as e:
            print(f"study: {e}", file=sys.stderr)
            return 2
        for path in paths:
            print(f"study: plot {path}")
    if result.failed:
        return 1
    return 3 if args.fail_on_criteria and result.failed_criteria else 0
