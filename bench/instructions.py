"""Instruction counts (valgrind's callgrind): sbsim against plain `sumo` on the same grid, with no
story and with the six-story set. Unlike wall time on a shared 2-vCPU machine, the counts repeat
to a fraction of a percent, so they show what a change does when the timings drown in noise (they
do not show waiting, cache misses or threads working side by side: read both).

    .venv/bin/python bench/instructions.py [--preset bench5k] [--end 60] [--compare EXE ...]
        [--step-length 0.1] [--from-state 120] [--threads 1]

--from-state T runs --end seconds from a state saved at T s (made once with plain `sumo`), as a run
with the grid full is measured without its insertion ramp; --step-length sets SUMO's step.

Runs are ~50x slower under callgrind; two run side by side.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from benchlib import Window, sbsim

STORY = Path(__file__).resolve().parent / "stories" / "six_stories.py"


def instructions(cmd: list[str], keep: Path | None = None) -> int:
    """The instructions callgrind counted for cmd (the whole process, start-up included); its
    profile is kept as `keep` if given (callgrind_annotate --inclusive=yes reads it)."""
    with tempfile.TemporaryDirectory() as tmp:
        out = keep or Path(tmp) / "callgrind.out"
        subprocess.run(
            # Children traced: a wrapper script that execs the program (a build's `run`, setting
            # LD_LIBRARY_PATH) is counted as the program it runs, not as the shell alone.
            ["valgrind", "--tool=callgrind", "--trace-children=yes", f"--callgrind-out-file={out}", *cmd],
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
    parser.add_argument("--step-length", type=float, help="SUMO's step in seconds (default: the preset's)")
    parser.add_argument("--from-state", type=float, metavar="T", help="run --end seconds from a state saved at T s")
    parser.add_argument("--threads", help="sbsim's --threads (default: sbsim's own)")
    parser.add_argument("--keep", type=Path, metavar="DIR", help="keep each run's callgrind profile in DIR")
    parser.add_argument("--story", type=Path, default=STORY, help="the story set (default: the six stories)")
    args = parser.parse_args()

    window = Window(args.preset, args.end, args.step_length, args.from_state)
    commands = {"sumo": window.sumo_command()}
    threads = ["--threads", args.threads] if args.threads is not None else []
    # Another build's name is its path when its file name is taken (builds are all called sbsim).
    builds = [("sbsim", sbsim())]
    for exe in args.compare:
        builds.append((Path(exe).name if Path(exe).name not in dict(builds) else exe, exe))
    for name, exe in builds:
        commands[name] = window.sbsim_command(exe, "--quiet", *threads)
        commands[f"{name} + {args.story.stem.replace('_', ' ')}"] = window.sbsim_command(
            exe, "--quiet", *threads, "--story", str(args.story)
        )
    print(f"{window.describe()}, under callgrind ...", flush=True)
    if args.keep:
        args.keep.mkdir(parents=True, exist_ok=True)
    keeps = [
        args.keep / f"callgrind.{re.sub(r'[^A-Za-z0-9.]+', '_', name)}.out" if args.keep else None for name in commands
    ]
    with ThreadPoolExecutor(max_workers=2) as pool:
        counts = dict(zip(commands, pool.map(instructions, commands.values(), keeps), strict=True))
    base = counts["sumo"]
    width = max(36, *(len(name) for name in counts))
    print(f"\n{'command':<{width}} {'instructions':>15} {'ratio':>7}")
    for name, count in counts.items():
        print(f"{name:<{width}} {count / 1e9:13.3f} G {count / base:6.3f}x")


if __name__ == "__main__":
    main()
