"""The link budget in tiers against the exact model (issue "fast radio"): Sepulcre et al.'s highway at
its loaded setting (β = 0.12 veh/m, 25 Hz, bench/radio.py's `dense` configuration), every seed run
three times — `[performance] link_budget = "exact"`, the tiers with every link per receiver
(`far_cell_m = 0`) and the default tiers with the far tier's cells (`far_cell_m = 100`) — and the
delivery ratio per 25 m bin of each printed with its difference from the exact model's (bound: 0.01
per bin), then the interference the model neglects: the mean power at a receiver from every station
beyond the cutoff range (the only links no tier computes), from the model's own WINNER+ B1 law,
against the noise.

    PYTHONPATH=python:tools .venv/bin/python bench/tiers.py [--seconds 4] [--seeds 3] [--tier-margin 7 5 ...]

Each mode's error is printed beside its runs' CPU seconds (user + sys, all seeds) and their ratio to the exact model's.
With several seeds it is also printed over seeds: per 50 m bin (two 25 m points), each seed's difference from the
exact model's run of that seed, their mean and its standard error.
"""

from __future__ import annotations

import argparse
import math
import resource
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from benchlib import mean_se  # noqa: E402
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


def over_seeds(curves: dict[str, list[dict]], labels: dict[str, str]) -> None:
    """Per 50 m bin (the 25 m points 2j and 2j + 1), the mean over seeds of each seed's difference from
    its exact run, ± its standard error: a seed is one sample of the draws and of who collides with whom,
    so the spread between seeds says how far a mean is from the modes' own difference."""
    bins = [(k, k + 1) for k in range(0, len(DISTANCES) - 1, 2)]

    def ratio(curve: dict, pair: tuple[int, int]) -> float | None:
        n = sum(curve["links"][k] for k in pair)
        return sum(curve["received"][k] for k in pair) / n if n else None

    exact = curves["exact"]
    print(f"\nover {len(exact)} seeds, mean Δ vs exact ± s.e. per 50 m bin (25 m points merged):")
    print(f"{'metres':>8}" + "".join(f" {f'{DISTANCES[a]:.0f}+{DISTANCES[b]:.0f}':>15}" for a, b in bins))
    for mode in curves:
        if mode == "exact":
            continue
        row, worst = "", (0.0, 0.0, 0.0)
        for pair in bins:
            diffs = [
                rb - ra
                for a, b in zip(exact, curves[mode], strict=True)
                if (ra := ratio(a, pair)) is not None and (rb := ratio(b, pair)) is not None
            ]
            if len(diffs) < 2:
                row += f" {'-':>15}"
                continue
            m, se = mean_se(diffs)
            row += f" {m:+7.4f}±{se:.4f}"
            if abs(m) > abs(worst[0]):
                worst = (m, se, DISTANCES[pair[0]])
        print(f"{mode:>8}{row}")
        print(f"{'':>8} {labels[mode]}: largest mean Δ {worst[0]:+.4f} ± {worst[1]:.4f} at {worst[2]:.0f} m")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seconds", type=float, default=4.0, help="simulated seconds per run (default 4)")
    parser.add_argument("--seeds", type=int, default=3, help="seeds per mode, pooled (default 3)")
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument(
        "--tier-margin",
        type=float,
        nargs="*",
        default=[],
        metavar="DB",
        help="also run the far cells with each of these tier margins (dB; default 10): the interference-only tier "
        "starts nearer (7 dB: 430 m instead of 512 m at bench5k's 23 dBm; here the far cells still start at the "
        "trace's 520 m, which these runs need for their lost lines)",
    )
    args = parser.parse_args()

    c = CONFIGS["dense"]
    modes: dict[str, tuple[str, ...]] = {
        "exact": ("--param", "radio_link_budget=exact"),
        "links": ("--param", "radio_link_budget=tiers", "--param", "radio_far_cell_m=0"),
        "cells": ("--param", "radio_link_budget=tiers"),
    }
    labels = {"links": "tiers per link", "cells": "tiers with far cells"}
    for margin in args.tier_margin:
        mode = f"m{margin:g}"
        modes[mode] = ("--param", "radio_link_budget=tiers", "--param", f"radio_tier_margin_db={margin:g}")
        labels[mode] = f"far cells, tier margin {margin:g} dB"
    curves: dict[str, list[dict]] = {mode: [] for mode in modes}
    cpu: dict[str, float] = {mode: 0.0 for mode in modes}  # the runs' own CPU (user + sys), s
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(1, args.seeds + 1):
            for mode, extra in modes.items():
                before = resource.getrusage(resource.RUSAGE_CHILDREN)
                curves[mode].append(run(c, args.seconds, Path(tmp), args.threads, seed, extra))
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                cpu[mode] += after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
    pooledBy = {mode: pooled(curves[mode]) for mode in modes}
    exact = pooledBy["exact"]
    compared = [mode for mode in modes if mode != "exact"]
    print(
        f"β = {c.density} veh/m, {c.hz:g} Hz, {args.seconds:g} s x {args.seeds} seeds; mean CBR "
        + ", ".join(f"{mode} {pooledBy[mode]['cbr']:.3f}" for mode in modes)
    )
    print(f"\n{'metres':>6} {'exact':>7}" + "".join(f" {mode:>7} {'diff':>7}" for mode in compared) + f" {'links':>9}")
    worst = {mode: 0.0 for mode in compared}
    for k, d in enumerate(DISTANCES):
        a = exact["pdr"][k]
        if a is None:
            continue
        row = f"{d:6.0f} {a:7.4f}"
        for mode in compared:
            b = pooledBy[mode]["pdr"][k]
            if b is None:
                row += f" {'-':>7} {'-':>7}"
                continue
            worst[mode] = max(worst[mode], abs(a - b))
            row += f" {b:7.4f} {b - a:+7.4f}"
        print(row + f" {exact['links'][k]:9d}")
    print(f"\n{'mode':<34} {'largest diff':>12} {'bound 0.01':>10} {'mean CBR':>8} {'CPU s':>7} {'x exact':>7}")
    print(f"{'exact model':<34} {0:12.4f} {'':>10} {exact['cbr']:8.3f} {cpu['exact']:7.1f} {1:7.2f}")
    for mode in compared:
        w = worst[mode]
        print(
            f"{labels[mode]:<34} {w:12.4f} {'within' if w <= 0.01 else 'OUTSIDE':>10} {pooledBy[mode]['cbr']:8.3f} "
            f"{cpu[mode]:7.1f} {cpu[mode] / cpu['exact']:7.2f}"
        )
    if args.seeds > 1:
        over_seeds(curves, labels)
    neglected = neglected_dbm(c.density, c.hz)
    print(
        f"\ncutoff {cutoff_m():.0f} m; neglected interference beyond it: {neglected:.1f} dBm, "
        f"{NOISE - neglected:.1f} dB below the noise ({NOISE:g} dBm; bound: more than 10 dB)"
    )


if __name__ == "__main__":
    main()
