"""Obstacles at scale (issue 28): the channel model's buildings on a built-up city, every vehicle
running Artery's CaService, the run with its buildings against the same run without them.

    PYTHONPATH=python .venv/bin/python bench/obstacles.py [--scenario DIR] [--end 200] [--runs 3]
        [--threads 1 2] [--compare OLD_SBSIM ...] [--traces]

`--scenario DIR`: Artery's Erlangen (its SUMO files are Veins' examples/veins: erlangen.sumo.cfg,
.net.xml, .rou.xml, .poly.xml with 743 polygons of type "building"). Without it, a built-up grid
made here (netgenerate, randomTrips and a building polygon on each plot of each block; fixed
seeds), so the benchmark runs on a fresh machine. "without" is the same sumocfg without its
polygon file (no obstacles loaded); both use the channel model's defaults (9 dB a wall, 0.4 dB/m).

Per run: CPU s (user + sys) and wall s, medians of interleaved runs, peak RSS, vehicles, obstacles
loaded and obstacle links evaluated (the summary's lines), CAMs delivered, and the ratio with/
without buildings (the median over rounds of the ratio within a round, CPU and wall).
`--compare` runs other sbsim builds alike (before/after); `--traces` checks that the message
traces are byte-identical across thread counts and builds.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import random
import re
import statistics
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from benchlib import OUT, Run, alternate, median, sbsim  # noqa: E402
from sbsim.scenarios.grid import make_grid  # noqa: E402

GRID = 10  # junctions per side
SPACING = 150.0  # m between junctions
SETBACK = 12.0  # m from a road's centre line to the plots
PLOTS = 3  # plots per block side: 9 buildings a block, 729 on the grid (Erlangen has 743)


def built_up_grid(folder: Path) -> Path:
    """A grid city with a building on each plot of each block and random trips; its .sumocfg."""
    cfg = folder / "city.sumocfg"
    if cfg.exists():
        return cfg
    print(f"generating the built-up grid in {folder} ...", flush=True)
    made = make_grid(
        folder,
        name="city",
        grid=GRID,
        spacing=SPACING,
        traffic="trips",
        period=0.6,
        min_distance=600.0,
        end=1000.0,
        step_length=0.1,
        seed=28,
        additional_files="buildings.poly.xml",
    )
    rng = random.Random(28)
    root = ET.Element("additional")
    plot = (SPACING - 2 * SETBACK) / PLOTS
    for i in range(GRID - 1):
        for j in range(GRID - 1):
            for p in range(PLOTS):
                for q in range(PLOTS):
                    # A house inset 2-6 m on each side of its plot: yards and lanes between them.
                    x0 = i * SPACING + SETBACK + p * plot + rng.uniform(2, 6)
                    x1 = i * SPACING + SETBACK + (p + 1) * plot - rng.uniform(2, 6)
                    y0 = j * SPACING + SETBACK + q * plot + rng.uniform(2, 6)
                    y1 = j * SPACING + SETBACK + (q + 1) * plot - rng.uniform(2, 6)
                    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]
                    shape = " ".join(f"{x:.2f},{y:.2f}" for x, y in corners)
                    attributes = {"id": f"b{i}_{j}_{p}_{q}", "type": "building", "color": "1,0,0", "shape": shape}
                    ET.SubElement(root, "poly", attributes)
    ET.indent(root)
    ET.ElementTree(root).write(folder / "buildings.poly.xml", encoding="utf-8", xml_declaration=True)
    return made


def without_polygons(cfg: Path, folder: Path) -> Path:
    """A copy of the sumocfg without its additional (polygon) files, its other files absolute."""
    tree = ET.parse(cfg)
    inputs = tree.getroot().find("input")
    if inputs is None:
        sys.exit(f"{cfg}: no <input> section")
    for element in list(inputs):
        if element.tag == "additional-files":
            inputs.remove(element)
        elif element.tag in ("net-file", "route-files"):
            files = [str((cfg.parent / f.strip()).resolve()) for f in element.get("value", "").split(",")]
            element.set("value", ",".join(files))
    target = folder / f"{cfg.stem}.no-buildings.sumocfg"
    tree.write(target, encoding="utf-8", xml_declaration=True)
    return target


def summary(stdout: str, pattern: str) -> str:
    """A number from sbsim's summary, or '-'."""
    m = re.search(pattern, stdout, re.MULTILINE)
    return m.group(1) if m else "-"


def paired(runs: list[Run], base: list[Run], what: str) -> float:
    """The median over rounds of this run's time over the base run's in the same round."""
    return statistics.median(getattr(a, what) / getattr(b, what) for a, b in zip(runs, base, strict=True))


def digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()[:16]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scenario", type=Path, help="Artery's Erlangen folder (default: a generated built-up grid)")
    parser.add_argument("--end", type=float, default=200.0, help="simulated seconds (default 200)")
    parser.add_argument("--runs", type=int, default=3, help="runs per command (default 3)")
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 2], help="--threads values (default 1 2)")
    parser.add_argument("--compare", nargs="*", default=[], metavar="EXE", help="other sbsim builds to run alike")
    parser.add_argument("--traces", action="store_true", help="check the message traces are byte-identical")
    args = parser.parse_args()

    folder = OUT / "obstacles"
    folder.mkdir(parents=True, exist_ok=True)
    if args.scenario:
        configs = sorted(args.scenario.glob("*.sumo.cfg")) + sorted(args.scenario.glob("*.sumocfg"))
        if not configs:
            sys.exit(f"{args.scenario}: no .sumo.cfg or .sumocfg")
        cfg = configs[0].resolve()
    else:
        cfg = built_up_grid(folder / "city")
    bare = without_polygons(cfg, folder)
    services = folder / "ca.services.xml"
    services.write_text('<services><service type="artery.application.CaService"/></services>\n')
    radio = folder / "radio.toml"
    radio.write_text("# the channel model's defaults: [obstacles] polygon_type building, wall_db 9, per_metre_db 0.4\n")

    builds = {"": sbsim(), **{f" [{k + 1}]": exe for k, exe in enumerate(args.compare)}}
    commands: dict[str, list[str]] = {}
    traces: dict[str, Path] = {}
    for label, exe in builds.items():
        for threads in args.threads:
            for name, config in (("with", cfg), ("without", bare)):
                key = f"{name} t{threads}{label}"
                cmd = [exe, "--sumocfg", str(config), "--services", str(services), "--radio", str(radio)]
                cmd += ["--end", f"{args.end:g}", "--threads", str(threads)]
                if args.traces:
                    traces[key] = folder / f"trace-{len(traces)}.jsonl"
                    cmd += ["--messages", str(traces[key])]
                commands[key] = cmd
    for k, exe in enumerate(args.compare):
        print(f"[{k + 1}] = {exe}")
    print(f"{cfg.name}, {args.end:g} s simulated, CaService on every vehicle, {args.runs} runs each, interleaved")
    results = alternate(commands, args.runs)

    print(
        f"\n{'run':<16} {'cpu s':>7} {'wall s':>7} {'RSS MB':>7} {'vehicles':>8} {'obstacles':>9} "
        f"{'obstacle links':>14} {'CAMs delivered':>14} {'x cpu':>6} {'x wall':>6}"
    )
    for key, runs in results.items():
        first = runs[0].stdout
        ratio_cpu = ratio_wall = ""
        base_key = key.replace("with ", "without ", 1)
        if key.startswith("with ") and base_key in results:
            ratio_cpu = f"{paired(runs, results[base_key], 'cpu'):.2f}"
            ratio_wall = f"{paired(runs, results[base_key], 'wall'):.2f}"
        vehicles = summary(first, r"^peak running: (\d+)")
        obstacles = summary(first, r"^obstacles: (\d+)")
        links = summary(first, r"^obstacle links: (\d+)")
        delivered = summary(first, r"^messages CAM: sent \d+, delivered (\d+)")
        print(
            f"{key:<16} {median([r.cpu for r in runs]):7.2f} {median([r.wall for r in runs]):7.2f} "
            f"{median([r.rss_mb for r in runs]):7.0f} {vehicles:>8} {obstacles:>9} {links:>14} {delivered:>14} "
            f"{ratio_cpu:>6} {ratio_wall:>6}"
        )
    if args.traces:
        print("\nmessage traces (sha256, first 16 hex digits):")
        for name in ("with", "without"):
            digests = {key: digest(path) for key, path in traces.items() if key.startswith(name + " ")}
            same = len(set(digests.values())) == 1
            print(f"  {name} buildings: {'identical' if same else 'DIFFERENT'} across {', '.join(digests)}")
            if not same:
                for key, value in digests.items():
                    print(f"    {key:<16} {value}")
    load = os.getloadavg()
    print(f"\nload average after the runs: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} ({os.cpu_count()} CPUs)")


if __name__ == "__main__":
    main()
