"""An interference-free sender against the closed form (issue "faithful V2X"): one vehicle beacons
every 2 ms on a straight road, twenty others stand 25 … 500 m behind it and never send, so no frame
meets another. The delivery ratio at distance d is then

    P(d) = E[ 1{P ≥ S} · (1 − FER(Eb/N0)) ],   P = P̄(d) + X + F,   Eb/N0 = P − N + 10 log10(B/R),

X ~ N(0, σ²) the log-normal shadowing (drawn per frame: bench/radio.toml's correlation 0), F the
Nakagami-m fading gain in dB (with --fading), S the sensing threshold, N the noise, FER Goubet's
table interpolated in dB. This script computes P(d) from the model's own formulas (WINNER+ B1,
Goubet's table), integrated numerically with numpy, and prints it beside sbsim's measured ratio.

    .venv/bin/python bench/closed_form.py [--frames 20000] [--fading]
"""

from __future__ import annotations

import argparse
import math
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from benchlib import sbsim  # noqa: E402
from sbsim.messages import read_messages  # noqa: E402
from sbsim.sumo import sumo_binary  # noqa: E402

RADIO = Path(__file__).resolve().parent / "radio.toml"
POWER, NOISE, SENSING, SIGMA = 23.0, -95.0, -85.0, 3.0  # bench/radio.toml
FREQUENCY, BANDWIDTH, RATE = 5.89e9, 10e6, 6e6
GOUBET = [(0, 1), (5, 1), (10, 0.4), (15, 1.5e-2), (20, 4e-3), (25, 3e-3), (30, 2e-3), (35, 1e-3)]
DISTANCES = [25 * k for k in range(1, 21)]
INTERVAL = 0.002  # s between frames: 344 µs on air, never two at once


def winner_b1(d: float) -> float:
    """WINNER+ B1 LOS at 5.89 GHz, antennas 1.5 m, environment 0.5 m, never below free space."""
    ghz = FREQUENCY / 1e9
    breakpoint_m = 4 * 1.0 * 1.0 * FREQUENCY / 299_792_458.0
    log_d = math.log10(max(d, 1.0))
    winner = 22.7 * log_d + 27 + 20 * math.log10(ghz) if d < breakpoint_m else 40 * log_d + 7.56 + 2.7 * math.log10(ghz)
    return max(winner, 20 * log_d + 46.4 + 20 * math.log10(ghz / 5.0))


def fer(ebn0_db: np.ndarray) -> np.ndarray:
    x, y = zip(*GOUBET, strict=True)
    return 10 ** np.interp(ebn0_db, x, np.log10(y))


def closed_form(d: float, nakagami_m: float | None) -> float:
    mean = POWER - winner_b1(d)
    xs = np.linspace(-8 * SIGMA, 8 * SIGMA, 3201)
    wx = np.exp(-0.5 * (xs / SIGMA) ** 2)
    if nakagami_m is None:
        gains, wg = np.zeros(1), np.ones(1)
    else:
        g = (np.arange(8000) + 0.5) * (40.0 / 8000)
        gains = 10 * np.log10(g)
        wg = g ** (nakagami_m - 1) * np.exp(-nakagami_m * g)
    power = mean + xs[:, None] + gains[None, :]
    success = np.where(power >= SENSING, 1 - fer(power - NOISE + 10 * math.log10(BANDWIDTH / RATE)), 0.0)
    weights = wx[:, None] * wg[None, :]
    return float((success * weights).sum() / weights.sum())


def scenario(folder: Path, frames: int) -> tuple[Path, Path]:
    (folder / "r.nod.xml").write_text('<nodes><node id="a" x="0" y="0"/><node id="b" x="1000" y="0"/></nodes>')
    (folder / "r.edg.xml").write_text('<edges><edge id="e" from="a" to="b" numLanes="1" speed="30"/></edges>')
    subprocess.run(
        [str(sumo_binary("netconvert")), "-n", "r.nod.xml", "-e", "r.edg.xml", "-o", "r.net.xml"],
        cwd=folder,
        check=True,
        capture_output=True,
    )
    # Standing still (a car moves at most 1 mm/s): the distances stay the stated ones.
    rows = ['<vehicle id="src" type="car" depart="0" route="r" departPos="600" departSpeed="0"/>']
    rows += [
        f'<vehicle id="r{d:03d}" type="car" depart="0" route="r" departPos="{600 - d}" departSpeed="0"/>'
        for d in DISTANCES
    ]
    (folder / "r.rou.xml").write_text(
        '<routes><vType id="car" maxSpeed="0.001" sigma="0"/><route id="r" edges="e"/>\n'
        + "\n".join(rows)
        + "\n</routes>"
    )
    cfg = folder / "r.sumocfg"
    cfg.write_text(
        '<configuration><input><net-file value="r.net.xml"/><route-files value="r.rou.xml"/></input>'
        f'<time><step-length value="0.1"/><end value="{frames * INTERVAL + 1:g}"/></time></configuration>'
    )
    services = folder / "services.xml"
    services.write_text(
        f'<services><service type="Beacon" interval="{INTERVAL}" bytes="138"><filters><name pattern="src"/>'
        '</filters></service><service type="Beacon" interval="1e9" bytes="1"><filters>'
        '<name pattern="src" match="inverse"/></filters></service></services>'
    )
    return cfg, services


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--frames", type=int, default=20000)
    parser.add_argument("--fading", action="store_true", help="Nakagami-m fading, m = 1.5, on top")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        cfg, services = scenario(folder, args.frames)
        radio = folder / "radio.toml"
        text = RADIO.read_text(encoding="utf-8")
        if args.fading:
            text = text.replace('fading = "none"', 'fading = "nakagami"\nnakagami_m = 1.5')
        radio.write_text(text, encoding="utf-8")
        messages = folder / "m.parquet"
        cmd = [sbsim(), "--sumocfg", str(cfg), "--services", str(services), "--radio", str(radio)]
        cmd += ["--messages", str(messages), "--messages-events", "tx,rx", "--quiet"]
        cmd += ["--end", f"{args.frames * INTERVAL + 0.05:g}"]
        done = subprocess.run(cmd, capture_output=True, text=True, check=False)
        if done.returncode != 0:
            sys.exit(f"{' '.join(cmd)} failed ({done.returncode}):\n{done.stderr}")
        table = read_messages(messages, columns=["event", "station"])
    sent = int(((table["event"] == "tx") & (table["station"] == "src")).sum())
    received = table[table["event"] == "rx"]["station"].value_counts()
    label = "Nakagami m = 1.5 and " if args.fading else ""
    print(f"one sender, {sent} frames, {label}σ = {SIGMA:g} dB shadowing per frame, no interference")
    print("| distance | sbsim | closed form | difference | standard error |")
    print("|---|---|---|---|---|")
    worst = 0.0
    for d in DISTANCES:
        got = received.get(f"r{d:03d}", 0) / sent
        expected = closed_form(d, 1.5 if args.fading else None)
        worst = max(worst, abs(got - expected))
        se = math.sqrt(max(expected * (1 - expected), 1e-12) / sent)
        print(f"| {d} m | {got:.4f} | {expected:.4f} | {got - expected:+.4f} | {se:.4f} |")
    print(f"largest difference {worst:.4f} (the issue's bound: 0.01)")


if __name__ == "__main__":
    main()
