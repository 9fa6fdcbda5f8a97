"""The link budget in tiers against the exact model (issue "fast radio"): Sepulcre et al.'s highway at
its loaded setting (β = 0.12 veh/m, 25 Hz, bench/radio.py's `dense` configuration), every seed run
three times — `[performance] link_budget = "exact"`, the tiers with every link per receiver
(`far_cell_m = 0`) and the default tiers with the far tier's cells (`far_cell_m = 100`) — and the
delivery ratio per 25 m bin of each printed with its difference from the exact model's (bound: 0.01
per bin), then the interference the model neglects: the mean power at a receiver from every station
beyond the cutoff range (the only links no tier computes), from the model's own WINNER+ B1 law,
against the noise.

    PYTHONPATH=python:tools .venv/bin/python bench/tiers.py [--seconds 4] [--seeds 3]
"""

from __future__ import annotations

import argparse
import math
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from closed_form import NOISE, POWER, RATE, SIGMA, winner_b1  # noqa: E402
from radio import CONFIGS, DISTANCES, LENGTH, pooled, run  # noqa: E402

FLOOR = -105.0  # dBm, the default interference floor
FRAME_BYTES = 220  # radio.py's beacon with its headers


def cutoff_m() -> float:
    """Where the mean power plus the cutoff's margin (2 σ, no fading) falls to the floor."""
    lo, hi = 1.0, 2.0
    while POWER - winner_b1(hi) + 2 * SIGMA >= FLOOR:
        lo, hi = hi, hi * 2
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if POWER - winner_b1(mid) + 2 * SIGMA >= FLOOR else (lo, mid)
    return hi


def neglected_dbm(density: float, hz: float) -> float:
    """The mean interference from stations beyond the cutoff at a receiver in the road's middle:
    each sends hz frames of FRAME_BYTES a second (its share of time on air), its mean power in mW
    (shadowing's linear mean), summed over a metre grid of the road both ways."""
    airtime = 40e-6 + math.ceil((16 + 8 * FRAME_BYTES + 6) / (RATE * 8e-6)) * 8e-6
    duty = hz * airtime
    gain = math.exp((SIGMA * math.log(10) / 10) ** 2 / 2)
    start = cutoff_m()
    total = 0.0
    d = start
    while d < LENGTH / 2:
        total += 2 * density * duty * gain * 10 ** ((POWER - winner_b1(d)) / 10)
        d += 1.0
    return 10 * math.log10(total) if total > 0 else -math.inf


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seconds", type=float, default=4.0, help="simulated seconds per run (default 4)")
    parser.add_argument("--seeds", type=int, default=3, help="seeds per mode, pooled (default 3)")
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument(
        "--tier-margin",
        type=float,
        default=None,
        help="also run the far cells with this tier margin (dB; default 10): the interference-only tier starts "
        "nearer (7 dB: 430 m instead of 512 m at bench5k's 23 dBm; here the far cells still start at the trace's "
        "520 m, which these runs need for their lost lines)",
    )
    args = parser.parse_args()

    c = CONFIGS["dense"]
    modes: dict[str, tuple[str, ...]] = {
        "exact": ("--param", "radio_link_budget=exact"),
        "links": ("--param", "radio_link_budget=tiers", "--param", "radio_far_cell_m=0"),
        "cells": ("--param", "radio_link_budget=tiers"),
    }
    if args.tier_margin is not None:
        modes["nearer"] = (
            "--param",
            "radio_link_budget=tiers",
            "--param",
            f"radio_tier_margin_db={args.tier_margin:g}",
        )
    curves: dict[str, list[dict]] = {mode: [] for mode in modes}
    seconds: dict[str, float] = {mode: 0.0 for mode in modes}
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(1, args.seeds + 1):
            for mode, extra in modes.items():
                began = time.perf_counter()
                curves[mode].append(run(c, args.seconds, Path(tmp), args.threads, seed, extra))
                seconds[mode] += time.perf_counter() - began
    exact, links, cells = (pooled(curves[mode]) for mode in ("exact", "links", "cells"))
    nearer = pooled(curves["nearer"]) if "nearer" in modes else None
    print(
        f"β = {c.density} veh/m, {c.hz:g} Hz, {args.seconds:g} s x {args.seeds} seeds; mean CBR exact "
        f"{exact['cbr']:.3f}, tiers per link {links['cbr']:.3f}, tiers with far cells {cells['cbr']:.3f}"
    )
    header = f"\n{'metres':>6} {'exact':>7} {'links':>7} {'diff':>7} {'cells':>7} {'diff':>7} {'links':>9}"
    print(header + (f" {'nearer':>7} {'diff':>7}" if nearer is not None else ""))
    worst = {"links": 0.0, "cells": 0.0, "nearer": 0.0}
    for k, d in enumerate(DISTANCES):
        a, b, e = exact["pdr"][k], links["pdr"][k], cells["pdr"][k]
        if a is None or b is None or e is None:
            continue
        worst["links"] = max(worst["links"], abs(a - b))
        worst["cells"] = max(worst["cells"], abs(a - e))
        row = f"{d:6.0f} {a:7.4f} {b:7.4f} {b - a:+7.4f} {e:7.4f} {e - a:+7.4f} {exact['links'][k]:9d}"
        if nearer is not None and nearer["pdr"][k] is not None:
            n = nearer["pdr"][k]
            worst["nearer"] = max(worst["nearer"], abs(a - n))
            row += f" {n:7.4f} {n - a:+7.4f}"
        print(row)
    labels = [("links", "tiers per link"), ("cells", "tiers with far cells")]
    if nearer is not None:
        labels.append(("nearer", f"far cells, tier margin {args.tier_margin:g} dB"))
        print(f"mean CBR with tier margin {args.tier_margin:g} dB: {nearer['cbr']:.3f}")
    for mode, label in labels:
        w = worst[mode]
        print(
            f"\n{label}: largest difference per 25 m bin {w:.4f} (bound 0.01): {'within' if w <= 0.01 else 'OUTSIDE'}"
        )
    neglected = neglected_dbm(c.density, c.hz)
    print(
        f"cutoff {cutoff_m():.0f} m; neglected interference beyond it: {neglected:.1f} dBm, "
        f"{NOISE - neglected:.1f} dB below the noise ({NOISE:g} dBm; bound: more than 10 dB)"
    )
    print(
        f"wall seconds of all runs: exact {seconds['exact']:.1f}, tiers per link {seconds['links']:.1f}, "
        f"with far cells {seconds['cells']:.1f}"
    )


if __name__ == "__main__":
    main()
