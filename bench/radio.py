"""802.11p radio benchmark: Sepulcre et al., "Analytical Models of the Performance of IEEE 802.11p
Vehicle to Vehicle Communications", IEEE TVT 71(1), 2022 (arXiv 2104.07923), reproduced through
the real path: a SUMO highway (5 km, straight, 3 lanes each way, made by netconvert), vehicles
spread evenly at density β over its lanes and driving at constant speed, every vehicle running the
built-in fixed-rate `Beacon` service (a 220-byte frame: the paper's 190 bytes and 30 of MAC, as
before frames had their real size), sbsim with `--radio` (the channel model's defaults: WINNER+
B1 LOS, σ = 3 dB drawn per frame, −85 dBm sensing, −95 dBm noise, Goubet's FER table). The
message trace streams through a FIFO; the packet delivery ratio every 25 m (bins 25 m wide,
centred on 0, 25, …, 500 m) is counted for senders in the middle kilometre, and the mean channel
busy ratio is the mean of those senders' CBR at their transmissions.

    PYTHONPATH=python:tools .venv/bin/python bench/radio.py [--json FILE] [--plot FILE.png]
        [--seconds 4] [--configs base p15 p30 r18 dense]

`--scale PRESET` instead times the grid benchmark (tools/make_grid.py presets, e.g. bench5k) with
every vehicle beaconing at 10 Hz: plain `sumo`, sbsim whose beacons never send (the floor: the
radio's share is what the others cost above it), sbsim with the disc model and sbsim with the
channel model (defaults), interleaved runs, medians, receptions per second of wall time; with
`--ca` also every vehicle running Artery's CaService (EN 302 637-2 rules) on both models, beside
the beacon rows: CAMs sent, receptions and CPU µs per reception above the silent floor.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import threading
from dataclasses import dataclass
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from benchlib import alternate, median, paired_ratio, sbsim, scenario, sumo  # noqa: E402
from sbsim.sumo import sumo_binary  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
LENGTH = 5000.0  # m
LANES = 3  # per direction
SPEED = 25.0  # m/s
DISTANCES = [25 * k for k in range(21)]
# Sepulcre et al., Fig. (β = 0.06 veh/m, 6 Mbit/s, 10 Hz, 23 dBm): PDR at distance, simulated.
PUBLISHED = [(175.0, 0.9), (268.0, 0.5), (345.0, 0.1)]
# The paper's 190-byte packets, framed as this check always framed them (190 + 30 bytes of MAC):
# a 220-byte frame. With real headers (82 bytes for a single-hop broadcast; radio.toml sends no
# security envelope) that is a 138-byte beacon.
BEACON_BYTES = 220 - 82


@dataclass(frozen=True)
class Config:
    name: str
    power_dbm: float
    rate_mbps: float
    density: float  # vehicles per metre of road, all lanes
    hz: float


CONFIGS = {
    "base": Config("base", 23, 6, 0.06, 10),
    "p15": Config("p15", 15, 6, 0.06, 10),
    "p30": Config("p30", 30, 6, 0.06, 10),
    "r18": Config("r18", 23, 18, 0.06, 10),
    "dense": Config("dense", 23, 6, 0.12, 25),
}


def netconvert() -> str:
    return str(sumo_binary("netconvert"))


def make_highway(folder: Path, c: Config) -> Path:
    """The network (both directions), the evenly spread vehicles, the services, the sumocfg."""
    folder.mkdir(parents=True, exist_ok=True)
    net = folder / "highway.net.xml"
    if not net.exists():
        (folder / "h.nod.xml").write_text(
            f'<nodes><node id="w" x="0" y="0"/><node id="e" x="{LENGTH:g}" y="0"/></nodes>\n'
        )
        (folder / "h.edg.xml").write_text(
            f'<edges><edge id="east" from="w" to="e" numLanes="{LANES}" speed="40"/>'
            f'<edge id="west" from="e" to="w" numLanes="{LANES}" speed="40"/></edges>\n'
        )
        subprocess.run(
            [netconvert(), "-n", folder / "h.nod.xml", "-e", folder / "h.edg.xml", "-o", net, "--no-turnarounds"],
            check=True,
            capture_output=True,
        )
    count = round(c.density * LENGTH)
    rows = []
    for k in range(count):
        x = (k + 0.5) / c.density  # along the road, every 1/β metres
        lane = k % (2 * LANES)
        edge, pos = ("east", x) if lane < LANES else ("west", LENGTH - x)
        rows.append(
            f'<vehicle id="v{k:05d}" type="car" depart="0" route="{edge}" departLane="{lane % LANES}" '
            f'departPos="{pos:.2f}" departSpeed="{SPEED:g}"/>'
        )
    routes = folder / f"{c.name}.rou.xml"
    routes.write_text(
        "<routes>\n"
        f'<vType id="car" speedFactor="1" speedDev="0" maxSpeed="{SPEED:g}" lcStrategic="-1" lcSpeedGain="0" '
        'lcKeepRight="0" sigma="0"/>\n'
        '<route id="east" edges="east"/><route id="west" edges="west"/>\n' + "\n".join(rows) + "\n</routes>\n"
    )
    services = folder / f"{c.name}.services.xml"
    services.write_text(
        f'<services><service type="Beacon" interval="{1 / c.hz:.6g}" bytes="{BEACON_BYTES}"/></services>\n'
    )
    cfg = folder / f"{c.name}.sumocfg"
    cfg.write_text(
        "<configuration><input>"
        f'<net-file value="highway.net.xml"/><route-files value="{routes.name}"/>'
        '</input><time><step-length value="0.1"/></time>'
        '<processing><collision.action value="none"/></processing>'
        '<report><no-step-log value="true"/><no-warnings value="true"/></report></configuration>\n'
    )
    return cfg


def run(c: Config, seconds: float, folder: Path, threads: int, seed: int, extra: tuple[str, ...] = ()) -> dict:
    """One run of config `c`; `extra` arguments go to sbsim as they are (e.g. more --param)."""
    cfg = make_highway(folder, c)
    services = folder / f"{c.name}.services.xml"
    fifo = Path(tempfile.mkdtemp()) / "messages.jsonl"
    os.mkfifo(fifo)
    cmd = [
        sbsim(),
        "--sumocfg",
        str(cfg),
        "--end",
        f"{seconds:g}",
        "--services",
        str(services),
        "--radio",
        str(ROOT / "bench" / "radio.toml"),
        "--param",
        f"radio_power_dbm={c.power_dbm:g}",
        "--param",
        f"radio_rate_mbps={c.rate_mbps:g}",
        "--param",
        "radio_trace_range=520",
        "--messages",
        str(fifo),
        "--messages-events",
        "tx,rx,lost",
        "--threads",
        str(threads),
        "--seed",
        str(seed),
        "--quiet",
        *extra,
    ]
    proc = subprocess.Popen(cmd, stderr=subprocess.PIPE, text=True)
    err: list[str] = []
    reader = threading.Thread(target=lambda: err.append(proc.stderr.read()))
    reader.start()
    lo, hi = (LENGTH - 1000) / 2, (LENGTH + 1000) / 2
    middle: dict[tuple[str, int], None] = {}
    received = [0] * len(DISTANCES)
    considered = [0] * len(DISTANCES)
    cbr_sum, cbr_n = 0.0, 0
    # Beacons of the first 0.5 s are left out: the channel load needs a window to be measured.
    warmup = 0.5
    with open(fifo) as trace:
        for line in trace:
            e = json.loads(line)
            if e["t"] < warmup:
                continue
            if e["event"] == "tx":
                if lo <= e["x"] <= hi:
                    middle[(e["station"], e["seq"])] = None
                    cbr_sum += e["cbr"]
                    cbr_n += 1
                continue
            if e["event"] not in ("rx", "lost"):
                continue
            key = (e["sender"], e["seq"])
            if key not in middle or e.get("reason") == "queue":
                continue
            k = int(e["distance"] / 25 + 0.5)
            if k >= len(DISTANCES):
                continue
            considered[k] += 1
            received[k] += e["event"] == "rx"
    proc.wait()
    reader.join()
    if proc.returncode != 0:
        sys.exit(f"sbsim failed ({proc.returncode}): {' '.join(cmd)}\n{''.join(err)[-2000:]}")
    pdr = [r / n if n else None for r, n in zip(received, considered, strict=True)]
    return {
        "power_dbm": c.power_dbm,
        "rate_mbps": c.rate_mbps,
        "density": c.density,
        "hz": c.hz,
        "distance_m": DISTANCES,
        "pdr": pdr,
        "cbr": cbr_sum / cbr_n if cbr_n else None,
        "links": considered,
        "received": received,
        "cbr_samples": cbr_n,
    }


def pooled(curves: list[dict]) -> dict:
    """One curve from runs that differ only in their seed: receptions and links summed per distance,
    the CBR averaged over every transmission (a seed fixes the beacon phases, so one seed is one
    sample of the channel's draws and of who collides with whom)."""
    first = curves[0]
    links = [sum(c["links"][k] for c in curves) for k in range(len(DISTANCES))]
    received = [sum(c["received"][k] for c in curves) for k in range(len(DISTANCES))]
    samples = sum(c["cbr_samples"] for c in curves)
    cbr = sum(c["cbr"] * c["cbr_samples"] for c in curves if c["cbr"] is not None) / samples if samples else None
    return {
        **{k: first[k] for k in ("power_dbm", "rate_mbps", "density", "hz", "distance_m")},
        "pdr": [r / n if n else None for r, n in zip(received, links, strict=True)],
        "cbr": cbr,
        "links": links,
        "received": received,
        "cbr_samples": samples,
        "seeds": [c["pdr"] for c in curves],
    }


def at(curve: dict, distance: float) -> float:
    """The curve's PDR at `distance`, linear between its points."""
    xs, ys = curve["distance_m"], curve["pdr"]
    for k in range(1, len(xs)):
        if xs[k] >= distance:
            t = (distance - xs[k - 1]) / (xs[k] - xs[k - 1])
            return ys[k - 1] + t * (ys[k] - ys[k - 1])
    return ys[-1]


def plot(curves: list[dict], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for c in curves:
        label = f"{c['power_dbm']:g} dBm, {c['rate_mbps']:g} Mbit/s, β={c['density']:g}, {c['hz']:g} Hz"
        ax.plot(c["distance_m"], c["pdr"], marker=".", label=f"sbsim: {label} (CBR {c['cbr']:.2f})")
    ax.plot(
        [d for d, _ in PUBLISHED],
        [p for _, p in PUBLISHED],
        "k*",
        markersize=12,
        label="Sepulcre et al. 2022, simulated (23 dBm, 6 Mbit/s, β=0.06, 10 Hz)",
    )
    ax.set_xlabel("distance between transmitter and receiver (m)")
    ax.set_ylabel("packet delivery ratio")
    ax.set_xlim(0, 500)
    ax.set_ylim(0, 1.02)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=120)


def scale(preset: str, end: float, runs: int, threads: int, floor_dbm: list[float], ca: bool = False) -> None:
    cfg = scenario(preset)
    services = cfg.parent / "beacon.services.xml"
    services.write_text('<services><service type="Beacon" interval="0.1" bytes="190"/></services>\n')
    ca_services = cfg.parent / "ca.services.xml"
    ca_services.write_text('<services><service type="artery.application.CaService"/></services>\n')
    # The floor: the same services, never sending (SUMO, snapshot, middleware triggers only).
    silent = cfg.parent / "silent.services.xml"
    silent.write_text('<services><service type="Beacon" interval="1e9" bytes="190"/></services>\n')
    defaults = cfg.parent / "radio-defaults.toml"
    defaults.write_text("# the channel model's defaults\n")
    base = [sbsim(), "--sumocfg", str(cfg), "--end", f"{end:g}", "--services", str(services), "--threads", str(threads)]
    floor_run = [str(silent) if arg == str(services) else arg for arg in base]
    commands = {
        "sumo": [sumo(), "-c", str(cfg), "--end", f"{end:g}"],
        "sbsim beacons silent": floor_run,
        "sbsim disc": base,
    }
    for floor in floor_dbm:
        name = "sbsim channel" + ("" if floor == -105 else f" floor {floor:g} dBm")
        commands[name] = [*base, "--radio", str(defaults), "--param", f"radio_interference_floor_dbm={floor:g}"]
    if ca:
        # Artery's CA service (EN 302 637-2 rules) on every vehicle instead of the 10 Hz beacon.
        with_ca = [str(ca_services) if arg == str(services) else arg for arg in base]
        commands["sbsim CaService disc"] = with_ca
        commands["sbsim CaService channel"] = [*with_ca, "--radio", str(defaults)]
    what = "beaconing at 10 Hz" + (" or running the CaService" if ca else "")
    print(f"{preset}, {end:g} s simulated, every vehicle {what}, {runs} runs each, interleaved")
    results = alternate(commands, runs)
    floor_cpu = median([r.cpu for r in results["sbsim beacons silent"]])
    print(
        f"\n{'command':<36} {'wall s':>8} {'cpu s':>8} {'x sumo':>7} {'sent':>10} {'delivered':>11} "
        f"{'rx/s wall':>10} {'µs cpu/rx':>10}"
    )
    for name, rs in results.items():
        wall = median([r.wall for r in rs])
        cpu = median([r.cpu for r in rs])
        ratio = paired_ratio(results, name)[0] if name != "sumo" else 1.0
        sent = delivered = rate = per = ""
        for line in rs[0].stdout.splitlines():
            m = re.fullmatch(r"messages (Beacon|CAM): sent (\d+), delivered (\d+)", line.strip())
            if m:
                sent, delivered = m.group(2), m.group(3)
                rate = f"{int(delivered) / wall:,.0f}"
                # The CPU above the silent floor (SUMO, snapshot, triggers), per reception.
                per = f"{1e6 * (cpu - floor_cpu) / int(delivered):.2f}" if int(delivered) else ""
        print(f"{name:<36} {wall:8.2f} {cpu:8.2f} {ratio:7.2f} {sent:>10} {delivered:>11} {rate:>10} {per:>10}")
    load = os.getloadavg()
    print(f"\nload average after the runs: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} ({os.cpu_count()} CPUs)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--configs", nargs="+", default=list(CONFIGS), choices=list(CONFIGS))
    parser.add_argument("--seconds", type=float, default=4.0, help="simulated seconds per run (default 4)")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--seed", type=int, default=23423, help="sbsim's seed: beacon phases and every radio draw")
    parser.add_argument(
        "--seeds",
        type=int,
        default=5,
        help="runs per curve, seeds --seed, --seed+1, ...; their counts pooled (default 5)",
    )
    parser.add_argument("--json", type=Path, help="write the curves here")
    parser.add_argument("--plot", type=Path, help="draw the curves and the published points (PNG)")
    parser.add_argument("--scale", metavar="PRESET", help="time this grid preset instead (e.g. bench5k)")
    parser.add_argument("--end", type=float, default=110.0, help="--scale: simulated seconds (default 110)")
    parser.add_argument("--runs", type=int, default=3, help="--scale: runs per command (default 3)")
    parser.add_argument(
        "--floor", type=float, nargs="+", default=[-105.0], help="--scale: interference floors to time (dBm)"
    )
    parser.add_argument(
        "--ca", action="store_true", help="--scale: also every vehicle running the CaService (disc and channel model)"
    )
    args = parser.parse_args()
    if args.scale:
        scale(args.scale, args.end, args.runs, args.threads, args.floor, args.ca)
        return

    folder = ROOT / "bench" / "out" / "radio"
    curves = []
    for name in args.configs:
        c = CONFIGS[name]
        runs = [run(c, args.seconds, folder, args.threads, args.seed + k) for k in range(args.seeds)]
        curve = pooled(runs)
        curves.append(curve)
        print(
            f"\n{c.power_dbm:g} dBm, {c.rate_mbps:g} Mbit/s, β = {c.density:g} veh/m, {c.hz:g} Hz: "
            f"mean CBR {curve['cbr']:.3f}"
        )
        print("  distance m " + " ".join(f"{d:5d}" for d in DISTANCES))
        print("  PDR        " + " ".join(f"{p:5.3f}" if p is not None else "    -" for p in curve["pdr"]))
        if name == "base":
            print("  against Sepulcre et al. (simulated):")
            for d, published in PUBLISHED:
                ours = at(curve, d)
                verdict = "ok" if abs(ours - published) <= 0.05 else "OFF"
                per_seed = [at({"distance_m": DISTANCES, "pdr": p}, d) for p in curve["seeds"]]
                spread = f"seeds {min(per_seed):.3f}-{max(per_seed):.3f}" if len(per_seed) > 1 else ""
                print(f"    {d:5.0f} m: published {published:.2f}, sbsim {ours:.3f}  ({verdict}, |Δ| ≤ 0.05)  {spread}")
        if name == "dense":
            print(f"  near the sender (25 m): PDR {curve['pdr'][1]:.3f} (a loaded channel: below 0.95 expected)")
    if args.json:
        hidden = ("links", "received", "cbr_samples", "seeds")
        args.json.write_text(json.dumps([{k: v for k, v in c.items() if k not in hidden} for c in curves], indent=1))
    if args.plot:
        plot(curves, args.plot)


if __name__ == "__main__":
    main()
