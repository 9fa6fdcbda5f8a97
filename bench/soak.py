"""Soak: one simulated hour with heavy churn, memory every 5 minutes, logs identical across runs.

The `soak` grid (`sbsim.scenarios.grid` preset: random trips, ~4 vehicles entering and leaving every
second) fills for a 20-minute warm-up (`--warmup`), then one simulated hour is measured with about
2,200 vehicles running. It runs with
bench/stories/soak_stories.py (overlapping caps, short stops, Likelihood and Deferring, sirens
signalled to services that exchange V2X messages; bench/stories/soak_services.xml).

It prints:
- the resident memory (RSS) every simulated 5 minutes of the hour, measured inside the process
  by the story set's probe, and its growth from minute 10 to minute 60 (target: under 2 %);
- the per-vehicle states held at the end (board, conditions, middlewares) beside the running
  vehicles: any more than are running would be state kept for vehicles that left;
- the event logs' SHA-256 of a second run with the same seed and of a run with --threads 1:
  they must equal the first run's.

    .venv/bin/python bench/soak.py                # the whole check (three one-hour runs)
    .venv/bin/python bench/soak.py --runs 1       # memory only
"""

from __future__ import annotations

import argparse
import hashlib
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from benchlib import ROOT, sbsim, scenario
from sbsim.summary import read_summary

STORIES = ROOT / "bench" / "stories"
GROWTH_TARGET = 0.02


def run_soak(out: Path, *, seed: int, threads: int, warmup: float, end: float, every: float) -> dict[str, Any]:
    """One run into `out`; returns its summary JSON plus the probe's (time, rss_kb, running) rows."""
    out.mkdir(parents=True, exist_ok=True)
    rss_log = out / "rss.txt"
    cmd = [
        sbsim(),
        "--sumocfg",
        str(scenario("soak")),
        "--story",
        str(STORIES / "soak_stories.py"),
        "--services",
        str(STORIES / "soak_services.xml"),
        "--seed",
        str(seed),
        "--threads",
        str(threads),
        "--warmup",
        str(warmup),
        "--end",
        str(end),
        "--events",
        str(out / "events.jsonl"),
        "--summary",
        str(out / "summary.json"),
        "--param",
        f"rss_log={rss_log}",
        "--param",
        f"rss_every={every}",
        "--quiet",
    ]
    started = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if proc.returncode != 0:
        sys.exit(f"sbsim failed ({proc.returncode}): {' '.join(cmd)}\n{proc.stderr[-2000:]}")
    summary = read_summary(out / "summary.json")
    summary["wall"] = time.perf_counter() - started
    summary["rss"] = [tuple(int(float(v)) for v in line.split()) for line in rss_log.read_text().splitlines()]
    summary["events_sha256"] = hashlib.sha256((out / "events.jsonl").read_bytes()).hexdigest()
    summary["events_lines"] = sum(1 for _ in (out / "events.jsonl").open("rb"))
    return summary


def rss_at(rows: list[tuple[int, ...]], t: float) -> int:
    """RSS (kB) of the last probe at or before simulated time t."""
    before = [rss for time_s, rss, _ in rows if time_s <= t]
    if not before:
        sys.exit(f"no memory probe at or before {t} s")
    return before[-1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--warmup", type=float, default=1200.0, help="seconds filling the grid first (default 1200)")
    parser.add_argument("--hour", type=float, default=3600.0, help="simulated seconds measured (default 3600)")
    parser.add_argument("--every", type=float, default=300.0, help="seconds between memory probes (default 300)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument(
        "--runs", type=int, choices=(1, 3), default=3, help="3: also the same-seed and --threads 1 runs (default)"
    )
    args = parser.parse_args()

    with tempfile.TemporaryDirectory(prefix="sbsim-soak-") as tmp:
        end = args.warmup + args.hour
        runs = {"seed": args.seed, "warmup": args.warmup, "end": end, "every": args.every}
        first = run_soak(Path(tmp) / "a", threads=2, **runs)
        print(
            f"soak: {args.warmup:.0f} s warm-up + {args.hour:.0f} s measured, seed {args.seed}, 2 threads, "
            f"wall {first['wall']:.0f} s"
        )
        print(
            f"vehicles seen {first['vehicles_seen']}, peak running {first['peak_running']}, "
            f"{first['events_lines']} event lines"
        )
        print(f"{'minute':>6} {'running':>8} {'RSS MB':>8}   (minutes of the measured hour; < 0: warm-up)")
        for time_s, rss_kb, running in first["rss"]:  # type: ignore[misc]
            print(f"{(time_s - args.warmup) / 60:6.0f} {running:8d} {rss_kb / 1024:8.1f}")
        rows = first["rss"]  # type: ignore[assignment]
        early, late = rss_at(rows, args.warmup + 600), rss_at(rows, end)
        growth = (late - early) / early
        verdict = "ok" if growth < GROWTH_TARGET else "OVER TARGET"
        print(
            f"RSS growth minute 10 -> {args.hour / 60:.0f}: {early / 1024:.1f} MB -> {late / 1024:.1f} MB = "
            f"{growth * 100:+.2f} % (target < {GROWTH_TARGET * 100:.0f} %: {verdict})"
        )
        held = first["held_at_end"]
        assert isinstance(held, dict)
        leak = any(held[k] != held["running"] for k in ("storyboard_vehicles", "middlewares")) or (
            held["condition_vehicles_max"] > held["running"]
        )
        print(
            f"held at the end: running {held['running']}, board states {held['storyboard_vehicles']}, "
            f"most kept by one condition {held['condition_vehicles_max']}, middlewares {held['middlewares']} "
            f"({'LEAK' if leak else 'ok'})"
        )
        print(f"event log sha256 {first['events_sha256']}")
        same = True
        if args.runs == 3:
            for label, threads in (("same seed again", 2), ("--threads 1", 1)):
                other = run_soak(Path(tmp) / label.replace(" ", "-"), threads=threads, **runs)
                equal = other["events_sha256"] == first["events_sha256"]
                same = same and equal
                print(f"event log sha256 {other['events_sha256']} ({label}: {'identical' if equal else 'DIFFERENT'})")
    sys.exit(0 if growth < GROWTH_TARGET and not leak and same else 1)


if __name__ == "__main__":
    main()
