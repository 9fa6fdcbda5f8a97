"""CAMs on each station's own clock against the random-phase beacon (issue "faithful V2X", part 2).

With one shared trigger every station's CA check ran at the same instant, so CAMs started within
a few milliseconds of each other and collided on the 802.11p model. This script runs the CA
service on the channel model, then a Beacon at the CAMs' measured rate and mean size (a beacon
draws its own random phase), and prints the delivery ratio per 50 m of both side by side and the
histogram of CAM start times within the 100 ms period. ``--before EXE`` adds the same CA run of
another build (e.g. one with the shared trigger) as a third column.

    .venv/bin/python bench/cam_clocks.py [--preset bench1k] [--step-length 0.1] [--end 60] [--before OLD_SBSIM]

SUMO's step is 0.1 s by default here, as V2X studies (and Artery) run it: with 1 s steps a vehicle's
position changes once a second, so every CA check that sees the change fires within the 100 ms after
the step, and CAMs bunch there however the stations' clocks are spread.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from benchlib import OUT, sbsim  # noqa: E402
from sbsim.scenarios.grid import make_preset  # noqa: E402

RADIO = Path(__file__).resolve().parent / "radio.toml"
BINS_SHOWN = 8  # 0-400 m


def run(executable: str, cfg: Path, services: str, folder: Path, end: float, seed: int) -> tuple[dict, list[dict]]:
    """The summary and the trace's tx lines of one run on the channel model."""
    (folder / "services.xml").write_text(services, encoding="utf-8")
    summary, messages = folder / "summary.json", folder / "messages.jsonl"
    cmd = [executable, "--sumocfg", str(cfg), "--end", f"{end:g}", "--seed", str(seed), "--radio", str(RADIO)]
    cmd += ["--services", str(folder / "services.xml"), "--summary", str(summary), "--quiet"]
    cmd += ["--messages", str(messages), "--messages-range", "0"]
    done = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed ({done.returncode}):\n{done.stderr}")
    sent = []
    with messages.open(encoding="utf-8") as lines:
        for line in lines:
            if '"tx"' in line:
                sent.append(json.loads(line))
    return json.loads(summary.read_text(encoding="utf-8")), sent


def ratios(summary: dict, kind: str) -> dict[int, float]:
    return {b["from_m"]: b["ratio"] for b in summary["messages"].get(kind, {}).get("delivery_ratio", [])}


def matched_beacon(sent: list[dict]) -> tuple[float, int]:
    """The CAMs' mean interval (s; each station's span over its CAMs after the first, pooled) and mean
    size (bytes): a beacon at that interval sends as many messages per vehicle-second."""
    times: dict[str, list[float]] = {}
    sizes = []
    for line in sent:
        if line["type"] == "CAM":
            times.setdefault(line["station"], []).append(line["t"])
            sizes.append(line["bytes"])
    span = sum(t[-1] - t[0] for t in times.values() if len(t) > 1)
    count = sum(len(t) - 1 for t in times.values() if len(t) > 1)
    return round(span / count, 3), round(statistics.fmean(sizes))


def preset_scenario(preset: str, step: float) -> Path:
    """The preset with SUMO's step `step`, generated once into bench/out/."""
    folder = OUT / f"{preset}-step{step:g}"
    cfg = folder / f"{preset}.sumocfg"
    if not cfg.exists():
        print(f"generating {preset} (step {step:g} s) in {folder} ...", flush=True)
        make_preset(folder, preset, step_length=step)
    return cfg


def histogram(sent: list[dict]) -> list[int]:
    """CAM starts per 10 ms of the 100 ms period."""
    offsets = Counter(int(round(line["t"] * 1e6) % 100_000) // 10_000 for line in sent if line["type"] == "CAM")
    return [offsets.get(k, 0) for k in range(10)]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--preset", default="bench1k", help="a grid preset of sbsim.scenarios.grid")
    parser.add_argument("--sumocfg", type=Path, help="a scenario instead of the preset")
    parser.add_argument("--step-length", type=float, default=0.1, help="SUMO's step for the preset (s)")
    parser.add_argument("--end", type=float, default=60.0)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--before", help="another sbsim executable whose CA run is shown beside")
    args = parser.parse_args()
    cfg = args.sumocfg or preset_scenario(args.preset, args.step_length)
    exe = sbsim()
    ca = '<services><service type="artery.application.CaService"/></services>'
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        (root / "ca").mkdir()
        ca_summary, ca_sent = run(exe, cfg, ca, root / "ca", args.end, args.seed)
        interval, size = matched_beacon(ca_sent)
        beacon = f'<services><service type="Beacon" interval="{interval}" bytes="{size}"/></services>'
        (root / "beacon").mkdir()
        beacon_summary, _ = run(exe, cfg, beacon, root / "beacon", args.end, args.seed)
        before = None
        if args.before:
            (root / "before").mkdir()
            before, before_sent = run(args.before, cfg, ca, root / "before", args.end, args.seed)

    cam, bea = ratios(ca_summary, "CAM"), ratios(beacon_summary, "Beacon")
    print(f"scenario {cfg}, {args.end:g} s, seed {args.seed}, channel model ({RADIO.name})")
    print(f"CAMs: {len(ca_sent)} sent, mean interval {interval} s, mean {size} bytes")
    print(f"beacons at that interval and size: {beacon_summary['messages']['Beacon']['sent']} sent")
    cbr = ca_summary.get("channel_busy_ratio", {})
    print(f"CBR with CAMs: mean {cbr.get('mean', 0):.4f}, max {cbr.get('max', 0):.4f}")
    header = "| distance | CAM, own clocks | beacon, random phase | difference |"
    if before is not None:
        header += " CAM, before |"
    print()
    print(header)
    print("|---|---|---|---|" + ("---|" if before is not None else ""))
    old = ratios(before, "CAM") if before is not None else {}
    for k in range(BINS_SHOWN):
        m = k * 50
        if m not in cam or m not in bea:
            continue
        row = f"| {m}-{m + 50} m | {cam[m]:.3f} | {bea[m]:.3f} | {cam[m] - bea[m]:+.3f} |"
        if before is not None:
            row += f" {old.get(m, float('nan')):.3f} |"
        print(row)
    print()
    print("CAM starts per 10 ms of the 100 ms period (own clocks):")
    counts = histogram(ca_sent)
    print("| ms | " + " | ".join(f"{10 * k}-{10 * k + 10}" for k in range(10)) + " |")
    print("|---" * 11 + "|")
    print("| CAMs | " + " | ".join(str(n) for n in counts) + " |")
    if before is not None:
        print("| before | " + " | ".join(str(n) for n in histogram(before_sent)) + " |")


if __name__ == "__main__":
    main()
