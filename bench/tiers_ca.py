"""The tier margin against the exact model on bench5k's CA run, over seeds (issue 28): CAMs whose
triggers follow the vehicles' dynamics (`ca.services.xml`, written by bench/scale.py), from the state
saved at 110 s, 0.1 s steps, every seed run with `[performance] link_budget = "exact"` and with the
default tiers (far cells) at each tier margin. A single seed of this run moves by ±0.01 per bin (its
burst of CAMs at 110 s sits on a DCC boundary, bench/README's w-cafar subsection), so the error is the
mean over seeds of each seed's difference from exact, per 50 m bin, with its standard error.

    PYTHONPATH=python:tools .venv/bin/python bench/tiers_ca.py [--exe SBSIM] [--seconds 2] [--seeds 1 2 ...] \
        [--tier-margin 10 7 5] [--json OUT.json]
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from benchlib import OUT, mean_se, sbsim  # noqa: E402

BINS = 9  # 0-450 m: beyond it every mode delivers nothing


def run(
    exe: str, folder: Path, seconds: float, seed: int, extra: tuple[str, ...], tmp: Path, services: str = "ca"
) -> dict:
    """One run; its summary's delivery ratio per 50 m bin (its one message type), CBR, frames and links."""
    summary = tmp / "summary.json"
    cmd = [exe, "-q", "--sumocfg", "bench5k.sumocfg", "--services", f"{services}.services.xml", "--threads", "1"]
    cmd += ["--radio", "radio-defaults.toml", "--seed", str(seed), "--summary", str(summary), *extra]
    cmd += ["--", "--load-state", "state110.xml.gz", "--begin", "110", "--end", f"{110 + seconds:g}"]
    cmd += ["--step-length", "0.1"]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, cwd=folder, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    s = json.loads(summary.read_text())
    (cam,) = s["messages"].values()
    bins = cam["delivery_ratio"][:BINS]
    return {
        "ratio": [b["ratio"] for b in bins],
        "stations": [b["stations"] for b in bins],
        "sent": cam["sent"],
        "delivered": cam["delivered"],
        "cbr": s["channel_busy_ratio"]["mean"],
        "links": s["links"],
        "cpu": after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument(
        "--exe", default=None, help="the sbsim to run (default: $SBSIM_EXECUTABLE or the installed one)"
    )
    parser.add_argument("--seconds", type=float, default=2.0, help="simulated seconds from 110 s (default 2)")
    parser.add_argument("--seeds", type=int, nargs="+", default=list(range(1, 9)))
    parser.add_argument("--tier-margin", type=float, nargs="+", default=[10.0, 7.0, 5.0], metavar="DB")
    parser.add_argument(
        "--services", default="ca", help="bench5k's services file: ca (default) or beacon (10 Hz, CBR ~0.87)"
    )
    parser.add_argument("--json", type=Path, default=None, help="also write every run's figures here")
    args = parser.parse_args()
    exe = args.exe or sbsim()
    folder = OUT / "bench5k"
    if not (folder / "ca.services.xml").exists():
        sys.exit(f"{folder}/ca.services.xml is missing: run bench/scale.py once with the ca-channel row")

    modes: dict[str, tuple[str, ...]] = {"exact": ("--param", "radio_link_budget=exact")}
    for margin in args.tier_margin:
        modes[f"{margin:g} dB"] = ("--param", "radio_link_budget=tiers", "--param", f"radio_tier_margin_db={margin:g}")
    runs: dict[str, list[dict]] = {mode: [] for mode in modes}
    with tempfile.TemporaryDirectory() as tmp:
        for seed in args.seeds:
            for mode, extra in modes.items():
                r = run(exe, folder, args.seconds, seed, extra, Path(tmp), args.services)
                runs[mode].append(r)
                print(
                    f"seed {seed:3d} {mode:>7}: sent {r['sent']:6d} CBR {r['cbr']:.4f} cpu {r['cpu']:6.2f} s  "
                    + " ".join(f"{v:.4f}" for v in r["ratio"]),
                    flush=True,
                )
                if args.json:
                    args.json.write_text(json.dumps({"seeds": args.seeds, "runs": runs}, indent=1))
    report(runs, args.seconds, args.seeds)


def report(runs: dict[str, list[dict]], seconds: float, seeds: list[int]) -> None:
    exact = runs["exact"]
    n = len(exact)
    print(f"\nbench5k, {seconds:g} s from 110 s at 0.1 s steps, {n} seeds; per 50 m bin (from metres):")
    print(f"{'':>8}" + "".join(f" {50 * k:>15d}" for k in range(BINS)))
    row = [mean_se([r["ratio"][k] for r in exact]) for k in range(BINS)]
    print(f"{'exact':>8}" + "".join(f" {m:7.4f}±{se:.4f}" for m, se in row))
    worst: dict[str, tuple[float, float, int]] = {}
    for mode, rs in runs.items():
        if mode == "exact":
            continue
        diffs = [mean_se([b["ratio"][k] - a["ratio"][k] for a, b in zip(exact, rs, strict=True)]) for k in range(BINS)]
        print(f"{mode + ' Δ':>8}" + "".join(f" {m:+7.4f}±{se:.4f}" for m, se in diffs))
        k = max(range(BINS), key=lambda j: abs(diffs[j][0]))
        worst[mode] = (diffs[k][0], diffs[k][1], 50 * k)
    print(
        f"\n{'mode':>8} {'largest mean Δ':>15} {'s.e.':>7} {'at m':>5} {'bound 0.01':>10} {'CBR':>7} {'CAMs':>7} "
        f"{'drawn M':>8} {'interf M':>8} {'CPU s':>7}"
    )
    for mode, rs in runs.items():
        cbr = sum(r["cbr"] for r in rs) / n
        sent = sum(r["sent"] for r in rs) / n
        drawn = sum(r["links"]["full"] for r in rs) / n / 1e6
        interf = sum(r["links"]["interference"] for r in rs) / n / 1e6
        cpu = sum(r["cpu"] for r in rs) / n
        m, se, at = worst.get(mode, (0.0, 0.0, 0))
        verdict = "" if mode == "exact" else ("within" if abs(m) <= 0.01 else "OUTSIDE")
        print(
            f"{mode:>8} {m:+15.4f} {se:7.4f} {at:5d} {verdict:>10} {cbr:7.4f} {sent:7.0f} {drawn:8.2f} {interf:8.2f} "
            f"{cpu:7.2f}"
        )


if __name__ == "__main__":
    main()
