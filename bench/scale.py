"""The radio at city scale (issue "fast radio"): the bench5k grid with every vehicle running, each
beaconing at 10 Hz (or running Artery's CaService), against plain `sumo` on the same window. The
window starts from a SUMO state saved once the grid is full (bench5k: 5,000 vehicles at 110 s), so
every figure is for the whole city, not for a grid that is still filling; `--step` sets SUMO's step
(1 s, or 0.1 s as V2X studies run it). Per row: wall and CPU seconds (medians of interleaved runs),
CPU and wall × sumo, peak RSS, messages sent and delivered, the link budget's links per tier, ns of
CPU per link (above the silent floor: the same run whose beacons never send) and µs per reception.

    PYTHONPATH=python:tools .venv/bin/python bench/scale.py [--preset bench5k] [--begin 110]
        [--window 30] [--step 1] [--threads 1 2] [--runs 3] [--rows sumo floor disc channel ...]
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from benchlib import Run, alternate, median, sbsim, scenario, sumo  # noqa: E402

SERVICES = {
    "beacon": '<services><service type="Beacon" interval="0.1" bytes="190"/></services>\n',
    "silent": '<services><service type="Beacon" interval="1e9" bytes="190"/></services>\n',
    "ca": '<services><service type="artery.application.CaService"/></services>\n',
}
ROWS = ["sumo", "floor", "disc", "channel", "channel-exact", "ca-disc", "ca-channel"]


def saved_state(cfg: Path, begin: float) -> Path:
    """The SUMO state at `begin`, saved once beside the scenario."""
    state = cfg.parent / f"state{begin:g}.xml.gz"
    if not state.exists():
        print(f"saving the SUMO state at {begin:g} s into {state} ...", flush=True)
        subprocess.run(
            [sumo(), "-c", str(cfg), "--end", f"{begin + 1:g}", "--save-state.times", f"{begin:g}"]
            + ["--save-state.files", str(state)],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            check=False,
        )
        if not state.exists():
            sys.exit(f"sumo saved no state at {begin:g} s (does the scenario run that long?)")
    return state


def figures(run: Run) -> dict[str, int]:
    """Messages and links from sbsim's summary."""
    out: dict[str, int] = {}
    for line in run.stdout.splitlines():
        if m := re.fullmatch(r"messages (\w+): sent (\d+), delivered (\d+)", line.strip()):
            out["sent"], out["delivered"] = int(m.group(2)), int(m.group(3))
        if m := re.fullmatch(r"links: (\d+) drawn in full, (\d+) interference only, (\d+) skipped.*", line.strip()):
            out["full"], out["interference"], out["skipped"] = (int(g) for g in m.groups())
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--preset", default="bench5k")
    parser.add_argument("--begin", type=float, default=110.0, help="s: the window starts here (default 110)")
    parser.add_argument("--window", type=float, default=30.0, help="simulated seconds (default 30)")
    parser.add_argument("--step", type=float, default=1.0, help="SUMO's step length in s (default 1)")
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--rows", nargs="+", default=ROWS, choices=ROWS)
    parser.add_argument("--exe", help="another sbsim to time (default: the installed one)")
    args = parser.parse_args()

    cfg = scenario(args.preset)
    state = saved_state(cfg, args.begin)
    for name, text in SERVICES.items():
        (cfg.parent / f"{name}.services.xml").write_text(text)
    (cfg.parent / "radio-defaults.toml").write_text("# the channel model's defaults\n")
    exe = args.exe or sbsim()
    end = args.begin + args.window
    window = ["--load-state", str(state), "--begin", f"{args.begin:g}", "--end", f"{end:g}"]
    window += ["--step-length", f"{args.step:g}"]

    def run(services: str, threads: int, *more: str) -> list[str]:
        return [
            exe,
            "--sumocfg",
            str(cfg),
            "--services",
            str(cfg.parent / f"{services}.services.xml"),
            "--threads",
            str(threads),
            *more,
            "--",
            *window,
        ]

    channel = ["--radio", str(cfg.parent / "radio-defaults.toml")]
    commands: dict[str, list[str]] = {}
    if "sumo" in args.rows:
        commands["sumo"] = [sumo(), "-c", str(cfg), *window]
    for t in args.threads:
        rows = {
            "floor": run("silent", t),
            "disc": run("beacon", t),
            "channel": run("beacon", t, *channel),
            "channel-exact": run("beacon", t, *channel, "--param", "radio_link_budget=exact"),
            "ca-disc": run("ca", t),
            "ca-channel": run("ca", t, *channel),
        }
        for name, cmd in rows.items():
            if name in args.rows:
                commands[f"{name} --threads {t}"] = cmd
    print(
        f"{args.preset}: {args.window:g} s from {args.begin:g} s (the grid full), step {args.step:g} s, "
        f"{args.runs} interleaved runs each"
    )
    results = alternate(commands, args.runs)

    base_cpu = median([r.cpu for r in results["sumo"]]) if "sumo" in results else None
    base_wall = median([r.wall for r in results["sumo"]]) if "sumo" in results else None
    print(
        f"\n{'command':<26} {'wall s':>8} {'cpu s':>8} {'cpu×':>6} {'wall×':>6} {'rss MB':>7} {'sent':>9} "
        f"{'delivered':>11} {'full links':>12} {'interf. links':>14} {'ns/link':>8} {'µs/rx':>6} {'M rx/cpu s':>10}"
    )
    for name, rs in results.items():
        wall, cpu = median([r.wall for r in rs]), median([r.cpu for r in rs])
        rss = max(r.rss_mb for r in rs)
        f = figures(rs[0])
        threads = name.rsplit(" ", 1)[-1]
        floor = results.get(f"floor --threads {threads}")
        above = cpu - median([r.cpu for r in floor]) if floor and not name.startswith("floor") else None
        links = f.get("full", 0) + f.get("interference", 0)
        ns_link = f"{1e9 * above / links:.1f}" if above is not None and links else ""
        us_rx = f"{1e6 * above / f['delivered']:.3f}" if above is not None and f.get("delivered") else ""
        # Receptions per CPU second of the whole run: the throughput a study sees.
        rx_rate = f"{f['delivered'] / cpu / 1e6:.1f}" if f.get("delivered") else ""
        cpu_x = f"{cpu / base_cpu:.2f}" if base_cpu else ""
        wall_x = f"{wall / base_wall:.2f}" if base_wall else ""
        print(
            f"{name:<26} {wall:8.2f} {cpu:8.2f} {cpu_x:>6} {wall_x:>6} {rss:7.0f} {f.get('sent', ''):>9} "
            f"{f.get('delivered', ''):>11} {f.get('full', ''):>12} {f.get('interference', ''):>14} "
            f"{ns_link:>8} {us_rx:>6} {rx_rate:>10}"
        )
    load = os.getloadavg()
    print(f"\nload average after the runs: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} ({os.cpu_count()} CPUs)")


if __name__ == "__main__":
    main()
