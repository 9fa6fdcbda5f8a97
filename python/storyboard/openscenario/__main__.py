"""`python -m storyboard.openscenario prepare --scenario X.xosc [--sumocfg C] [--param N=V] [--bind E=V]`:
prints one JSON object, what sbsim runs ({"sumocfg", "story", "sumo_options"}), or {"error": "..."}."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path


def _pairs(values: list[str], option: str) -> dict[str, str]:
    out = {}
    for v in values:
        name, eq, value = v.partition("=")
        if not eq or not name:
            raise ValueError(f"{option} {v}: expected NAME=VALUE")
        out[name] = value
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m storyboard.openscenario")
    parser.add_argument("command", choices=["prepare"])
    parser.add_argument("--scenario", required=True, type=Path)
    parser.add_argument("--sumocfg", type=Path)
    parser.add_argument("--param", action="append", default=[])
    parser.add_argument("--bind", action="append", default=[])
    args = parser.parse_args(argv)
    try:
        from .errors import ScenarioError  # noqa: PLC0415 - lxml missing is reported below
        from .prepare import prepare  # noqa: PLC0415
    except ImportError as e:
        print(json.dumps({"error": f"--scenario needs {e.name} (pip install lxml)"}))
        return 0
    try:
        result = prepare(args.scenario, args.sumocfg, _pairs(args.param, "--param"), _pairs(args.bind, "--bind"))
    except (ScenarioError, ValueError) as e:
        print(json.dumps({"error": str(e)}))
        return 0
    print(json.dumps(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
