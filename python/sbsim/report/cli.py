"""The report's command line (``python -m sbsim.report``; the older ``python -m storyboard.report`` too)."""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Sequence
from pathlib import Path

from sbsim.report.compose import build
from sbsim.report.html import to_html, write_pngs
from sbsim.report.loading import ReportError

PROG = "python -m sbsim.report"


def _same_file(a: Path, b: Path) -> bool:
    """Whether ``a`` and ``b`` are one file: the same inode when both exist (hard links, symlinks), else the
    same path once resolved."""
    try:
        return os.path.samefile(a, b)
    except OSError:
        return a.resolve() == b.resolve()


def _refuse_overwriting_inputs(args: argparse.Namespace) -> None:
    """Every file the report reads is an input before the page is written: ``-o`` naming one is refused, so
    the page can never replace the event log or trace it was made from."""
    inputs = {
        "the event log": args.events,
        "--sumocfg": args.sumocfg,
        "--story": args.story,
        "--fcd": args.fcd,
        "--summary": args.summary,
        "--messages": args.messages,
    }
    for name, path in inputs.items():
        if path is not None and _same_file(args.output, path):
            raise ReportError(f"-o: {args.output} is {name} ({path}); the report must not overwrite its input")


def main(argv: Sequence[str] | None = None) -> int:
    """Writes the page (and with ``--png`` the figures); bad input is one line on stderr and exit code 2."""
    parser = argparse.ArgumentParser(
        prog=PROG, description=sys.modules["sbsim.report"].__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("events", type=Path, help="the run's --events file (JSON Lines)")
    parser.add_argument("--sumocfg", type=Path, required=True, help="the run's SUMO configuration (for the net)")
    parser.add_argument("--story", type=Path, help="the run's story script: the map shows its areas (sbsim check)")
    parser.add_argument(
        "--param", action="append", default=[], metavar="NAME=VALUE", help="the run's --param values, for --story"
    )
    parser.add_argument("--fcd", type=Path, help="SUMO's FCD output of the run (positions and speeds)")
    parser.add_argument("--summary", type=Path, help="the run's --summary JSON")
    parser.add_argument("--messages", type=Path, help="the run's --messages trace: adds the V2X panels")
    parser.add_argument("-o", "--output", type=Path, required=True, help="the HTML file to write")
    parser.add_argument("--png", type=Path, metavar="DIR", help="also write each figure as DIR/<name>.png")
    args = parser.parse_args(argv)
    try:
        _refuse_overwriting_inputs(args)
        report = build(
            args.events,
            args.sumocfg,
            fcd=args.fcd,
            summary=args.summary,
            story=args.story,
            params=args.param,
            messages=args.messages,
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
