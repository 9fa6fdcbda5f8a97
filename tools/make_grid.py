#!/usr/bin/env python3
"""Generate a small, deterministic SUMO grid scenario for sbsim (the command line of
:mod:`sbsim.scenarios.grid`, where the scenarios and their parameters are described).

    python tools/make_grid.py OUT_DIR --preset bench5k
    python tools/make_grid.py OUT_DIR --grid 4 --end 200 --seed 1
    python tools/make_grid.py --list-presets
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
from collections.abc import Sequence
from pathlib import Path

# Run by path from a checkout (the C++ tests' fixtures do), where sbsim may not be installed: the
# package is this tree's python/ folder.
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "python"))

from sbsim.scenarios.grid import PRESETS, GridConfig, build  # noqa: E402


def parser() -> argparse.ArgumentParser:
    out = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter, epilog="presets: " + _presets()
    )
    out.add_argument("out_dir", nargs="?", type=Path, help="output folder")
    out.add_argument("--preset", choices=sorted(PRESETS), help="start from a preset")
    out.add_argument("--list-presets", action="store_true", help="print presets")
    GridConfig.add_arguments(out)
    return out


def _presets() -> str:
    return ", ".join(
        f"{k} ({v.grid}x{v.grid}, {v.lanes} lane(s), "
        + (f"{v.vehicles} loop vehicles" if v.traffic == "loops" else "trips")
        + ")"
        for k, v in PRESETS.items()
    )


def main(argv: Sequence[str] | None = None) -> int:
    """Writes the scenario and prints its .sumocfg's path; a bad parameter is one line on stderr, exit 2."""
    options = parser()
    args = options.parse_args(argv)
    if args.list_presets:
        for key, value in PRESETS.items():
            print(f"{key}: {value}")
        return 0
    if args.out_dir is None:
        options.error("out_dir is required")
    base = PRESETS[args.preset] if args.preset else GridConfig()
    try:
        path = build(args.out_dir, dataclasses.replace(base, **GridConfig.overrides(args)))
    except ValueError as exc:
        print(f"make_grid: {exc}", file=sys.stderr)
        return 2
    except (RuntimeError, FileNotFoundError) as exc:  # SUMO missing or one of its tools failing
        print(f"make_grid: {exc}", file=sys.stderr)
        return 1
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
