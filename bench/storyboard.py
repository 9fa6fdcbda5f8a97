"""Storyboard benchmark: story sets against plain `sumo` on grids with 1,000 to 20,000 running
vehicles. The sets: `six` (bench/stories/six_stories.py, one story per kind of work the storyboard
does each step) and `logic` (bench/stories/logic_stories.py: Hold, Not, Headway, Distance). Prints,
per grid and set, medians of interleaved runs, the wall-time ratio, and the storyboard's own time
per step and per vehicle-step (which should stay flat if the storyboard's time grows linearly with
the number of vehicles).
Targets for the six-story set: at most 1.10x sumo at 5,000 vehicles, 1.12x at 20,000.

    PYTHONPATH=python .venv/bin/python bench/storyboard.py [--presets bench1k bench5k bench20k]
        [--sets six logic] [--end 300] [--runs 3] [--step-length 0.1] [--from-state 120]

"own" is sbsim's own time, its wall time less its time in SUMO's steps, as a share of plain `sumo`'s
wall time (medians). --from-state T runs --end seconds from a state saved at T s (once, by plain
`sumo`); --step-length sets SUMO's step. --baseline also runs sbsim without a story: its own time
is what a run pays before any story (loading libsumo's libraries, SUMO loading the network and the
state, checking the inputs), and "stories' own" is a set's own time less that one's.
"""

from __future__ import annotations

import argparse
import re
from pathlib import Path

from benchlib import PRELOADS, Window, alternate, median, paired_ratio, preloaded, sbsim, scenario, summary_value

STORIES = Path(__file__).resolve().parent / "stories"
SETS = {"six": STORIES / "six_stories.py", "logic": STORIES / "logic_stories.py"}


def tenth_vehicle(cfg: Path) -> str:
    """The id of the routes file's 11th vehicle (the logic set's Distance target; ids differ by grid)."""
    ids = re.findall(r'<vehicle id="([^"]+)"', (cfg.parent / "routes.rou.xml").read_text())
    return ids[10]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--presets", nargs="+", default=["bench1k", "bench5k", "bench20k"])
    parser.add_argument("--sets", nargs="+", default=list(SETS), choices=list(SETS), help="story sets (default all)")
    parser.add_argument("--end", type=float, default=300.0, help="simulated seconds (default 300)")
    parser.add_argument("--runs", type=int, default=3, help="runs per command (default 3)")
    parser.add_argument(
        "--preload", nargs="*", default=[], choices=sorted(PRELOADS), help="also run sbsim with these allocators"
    )
    parser.add_argument(
        "--compare", nargs="*", default=[], metavar="EXE", help="also run these other sbsim executables (older builds)"
    )
    parser.add_argument("--step-length", type=float, help="SUMO's step in seconds (default: the preset's)")
    parser.add_argument("--from-state", type=float, metavar="T", help="run --end seconds from a state saved at T s")
    parser.add_argument("--baseline", action="store_true", help="also run sbsim without a story (its own time)")
    args = parser.parse_args()

    rows = []
    extras: list[str] = []  # per command: ratio to sumo round by round, peak RSS
    for preset in args.presets:
        window = Window(preset, args.end, args.step_length, args.from_state)
        cfg = scenario(preset)
        parameters = {"six": [], "logic": ["--param", f"target={tenth_vehicle(cfg)}"]}
        print(f"{window.describe()}, {args.runs} runs each, interleaved")
        sets = {
            f"sbsim + {name}": window.sbsim_command(sbsim(), "--story", str(SETS[name]), *parameters[name])
            for name in args.sets
        }
        commands = {"sumo": window.sumo_command(), **sets}
        if args.baseline:
            commands["sbsim, no story"] = window.sbsim_command(sbsim())
        first = next(iter(sets.values()))  # the extra builds and allocators run the first set
        for allocator in args.preload:
            commands[f"{args.sets[0]} + {allocator}"] = preloaded(allocator, first)
        for exe in args.compare:
            name = f"{args.sets[0]} {Path(exe).name}"
            commands[name if name not in commands else f"{args.sets[0]} {exe}"] = [exe, *first[1:]]
        results = alternate(commands, args.runs)
        base = median([r.wall for r in results["sumo"]])
        owns = {
            name: median([r.wall - summary_value(r.stdout, "time in sumo") for r in results[name]])
            for name in list(commands)[1:]
        }
        for name in list(commands)[1:]:
            paired, low, high = paired_ratio(results, name)
            rss = max(r.rss_mb for r in results[name])
            own = owns[name]
            stories = ""
            if "sbsim, no story" in owns and name != "sbsim, no story":
                extra = own - owns["sbsim, no story"]
                stories = f"  stories' own {extra:.2f} s = {100 * extra / base:.1f} %"
            extras.append(
                f"{preset:<10} {name:<28} {paired:.3f}x ({low:.3f}-{high:.3f})  own {own:.2f} s = "
                f"{100 * own / base:.1f} % of sumo{stories}  peak RSS {rss:.0f} MB"
            )
        extras.append(f"{preset:<10} {'sumo':<28} peak RSS {max(r.rss_mb for r in results['sumo']):.0f} MB")
        for name in sets:
            story_runs = results[name]
            steps = summary_value(story_runs[0].stdout, "steps")
            # Vehicle-steps: the grids hold their full count after the 100 s ramp, so use the peak.
            running = summary_value(story_runs[0].stdout, "peak running")
            board = median([summary_value(r.stdout, "time in storyboard") for r in story_runs])
            reading = median([summary_value(r.stdout, "time reading vehicles") for r in story_runs])
            rows.append(
                (
                    preset,
                    name.removeprefix("sbsim + "),
                    running,
                    median([r.wall for r in results["sumo"]]),
                    median([r.wall for r in story_runs]),
                    1000 * board / steps,
                    1e6 * board / (steps * running),
                    1000 * reading / steps,
                )
            )

    print(
        f"\n{'grid':<10} {'set':<6} {'vehicles':>8} {'sumo':>9} {'sbsim':>9} {'ratio':>7} "
        f"{'storyboard/step':>16} {'per vehicle-step':>17} {'reading/step':>13}"
    )
    for preset, story_set, running, base, wall, per_step, per_vehicle, reading in rows:
        print(
            f"{preset:<10} {story_set:<6} {running:8.0f} {base:7.2f} s {wall:7.2f} s {wall / base:6.3f}x "
            f"{per_step:13.2f} ms {per_vehicle:14.3f} us {reading:10.2f} ms"
        )
    print("\nratio to sumo per round, median (min-max), sbsim's own time (wall less time in SUMO), peak RSS:")
    print("\n".join(extras))


if __name__ == "__main__":
    main()
