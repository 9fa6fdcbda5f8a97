"""Instruction counts (valgrind's callgrind): sbsim against plain `sumo` on the same grid, with no
story and with the six-story set. Unlike wall time on a shared 2-vCPU machine, the counts repeat
to a fraction of a percent, so they show what a change does when the timings drown in noise (they
do not show waiting, cache misses or threads working side by side: read both).

    .venv/bin/python bench/instructions.py [--preset bench5k] [--end 60] [--compare EXE ...]

Runs are ~50x slower under callgrind; two run side by side.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from benchlib import sbsim, scenario, sumo

STORY = Path(__file__).resolve().parent / "stories" / "six_stories.py"


def instructions(cmd: list[str]) -> int:
    """The instructions callgrind counted for cmd (the whole process, start-up included)."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "callgrind.out"
        subprocess.run(
            ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", *cmd],
            check=True,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        match = re.search(r"^summary: (\d+)", out.read_text(), re.MULTILINE)
        if not match:
            raise RuntimeError(f"no instruction total from callgrind for {cmd}")
        return int(match.group(1))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--preset", default="bench5k", help="make_grid preset (default bench5k)")
    parser.add_argument("--end", type=float, default=60.0, help="simulated seconds (default 60)")
    parser.add_argument("--compare", nargs="*", default=[], metavar="EXE", help="other sbsim executables to count")
    args = parser.parse_args()

    cfg = str(scenario(args.preset))
    end = repr(args.end)
    commands = {"sumo": [sumo(), "-c", cfg, "--end", end]}
    for name, exe in [("sbsim", sbsim()), *((Path(e).name, e) for e in args.compare)]:
        commands[name] = [exe, "--sumocfg", cfg, "--end", end, "--quiet"]
        commands[f"{name} + six stories"] = [*commands[name], "--story", str(STORY)]
    print(f"{args.preset}, {args.end:g} s simulated, under callgrind ...", flush=True)
    with ThreadPoolExecutor(max_workers=2) as pool:
        counts = dict(zip(commands, pool.map(instructions, commands.values()), strict=True))
    base = counts["sumo"]
    print(f"\n{'command':<36} {'instructions':>15} {'ratio':>7}")
    for name, count in counts.items():
        print(f"{name:<36} {count / 1e9:13.3f} G {count / base:6.3f}x")


if __name__ == "__main__":
    main()
