"""Foundation benchmark: `sbsim --sumocfg X` (no story, snapshot included) against plain `sumo`
on the same grid with about 5,000 running vehicles. Runs them interleaved several times and
prints medians and the ratio. Target: sbsim at most 1.05x sumo's wall time.

    .venv/bin/python bench/foundation.py [--preset bench5k] [--end 300] [--runs 5]
"""

from __future__ import annotations

import argparse
from pathlib import Path

from benchlib import PRELOADS, alternate, median, paired_ratio, preloaded, sbsim, scenario, summary_value, sumo


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--preset", default="bench5k", help="make_grid preset (default bench5k)")
    parser.add_argument("--end", type=float, default=300.0, help="simulated seconds (default 300)")
    parser.add_argument("--runs", type=int, default=5, help="runs per command (default 5)")
    parser.add_argument(
        "--preload", nargs="*", default=[], choices=sorted(PRELOADS), help="also run sbsim with these allocators"
    )
    parser.add_argument(
        "--compare", nargs="*", default=[], metavar="EXE", help="also run these other sbsim executables (older builds)"
    )
    args = parser.parse_args()

    cfg = str(scenario(args.preset))
    end = repr(args.end)
    commands = {
        "sumo": [sumo(), "-c", cfg, "--end", end],
        "sbsim": [sbsim(), "--sumocfg", cfg, "--end", end],
        "sbsim --threads 1": [sbsim(), "--sumocfg", cfg, "--end", end, "--threads", "1"],
        # libsumo's own cost: stepping only, no vehicle read.
        "sbsim --no-snapshot": [sbsim(), "--sumocfg", cfg, "--end", end, "--no-snapshot"],
    }
    for allocator in args.preload:
        commands[f"sbsim + {allocator}"] = preloaded(allocator, commands["sbsim"])
    for exe in args.compare:
        commands[f"sbsim {Path(exe).name}"] = [exe, "--sumocfg", cfg, "--end", end]
    print(f"{args.preset}, {args.end:g} s simulated, {args.runs} runs each, interleaved")
    results = alternate(commands, args.runs)

    base_wall = median([r.wall for r in results["sumo"]])
    base_cpu = median([r.cpu for r in results["sumo"]])
    print(
        f"\n{'command':<28} {'median wall':>12} {'ratio':>7} {'per round (min-max)':>22} "
        f"{'median cpu':>11} {'ratio':>7} {'peak RSS':>9}"
    )
    for name, runs in results.items():
        wall = median([r.wall for r in runs])
        cpu = median([r.cpu for r in runs])
        rss = max(r.rss_mb for r in runs)
        paired, low, high = paired_ratio(results, name)
        print(
            f"{name:<28} {wall:10.2f} s {wall / base_wall:6.3f}x {paired:8.3f}x ({low:.3f}-{high:.3f}) "
            f"{cpu:9.2f} s {cpu / base_cpu:6.3f}x {rss:7.0f} MB"
        )

    single = results["sbsim --threads 1"]
    steps = summary_value(single[0].stdout, "steps")
    peak = summary_value(single[0].stdout, "peak running")
    reading = median([summary_value(r.stdout, "time reading vehicles") for r in single])
    in_sumo = median([summary_value(r.stdout, "time in sumo") for r in single])
    print(
        f"\none thread: {steps:.0f} steps, peak {peak:.0f} running; per step {1000 * in_sumo / steps:.2f} ms in SUMO, "
        f"{1000 * reading / steps:.2f} ms reading vehicles ({reading / in_sumo:.1%} of SUMO's time)"
    )


if __name__ == "__main__":
    main()
