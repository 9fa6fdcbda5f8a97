"""Cost of Artery's CA service on every vehicle: `sbsim --services` with CaService on all of
bench5k's ~5,000 running vehicles (the disc radio, 500 m), against the same run without services,
and (--beacon) with CaService at a fixed 10 Hz (`fixedRate`, a beacon on every trigger, for the
radio issue's beacon figure). CPU time (the machine is shared: wall time is noisy), medians.

    .venv/bin/python bench/services.py [--preset bench5k] [--end 60] [--runs 3]
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

from benchlib import alternate, median, sbsim, scenario, summary_value

CA = '<services><service type="artery.application.CaService"/></services>'
BEACON = '<services><service type="CaService" fixedRate="true"/></services>'


def messages(stdout: str, kind: str) -> tuple[int, int]:
    for line in stdout.splitlines():
        if line.startswith(f"messages {kind}: sent "):
            sent, delivered = line.split(": sent ")[1].split(", delivered ")
            return int(sent), int(delivered)
    return 0, 0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--preset", default="bench5k", help="make_grid preset (default bench5k)")
    parser.add_argument("--end", type=float, default=60.0, help="simulated seconds (default 60)")
    parser.add_argument("--runs", type=int, default=3, help="runs per command (default 3)")
    parser.add_argument("--beacon", action="store_true", help="also run CaService at a fixed 10 Hz (slow)")
    args = parser.parse_args()

    cfg = str(scenario(args.preset))
    end = repr(args.end)
    with tempfile.TemporaryDirectory() as tmp:
        ca, beacon = Path(tmp) / "ca.xml", Path(tmp) / "beacon.xml"
        ca.write_text(CA)
        beacon.write_text(BEACON)
        base = [sbsim(), "--sumocfg", cfg, "--end", end, "--threads", "1"]
        commands = {
            "sbsim (no services)": base,
            "sbsim + CaService (ETSI rules)": [*base, "--services", str(ca)],
        }
        if args.beacon:
            commands["sbsim + CaService fixedRate (10 Hz beacon)"] = [*base, "--services", str(beacon)]
        print(f"{args.preset}, {args.end:g} s simulated, {args.runs} runs each, interleaved, one thread")
        results = alternate(commands, args.runs)

    base_cpu = median([r.cpu for r in results["sbsim (no services)"]])
    print(
        f"\n{'command':<44} {'median wall':>12} {'median cpu':>11} {'extra cpu':>10} {'CAMs sent':>10} "
        f"{'delivered':>11} {'µs cpu/delivery':>16}"
    )
    for name, runs in results.items():
        wall = median([r.wall for r in runs])
        cpu = median([r.cpu for r in runs])
        sent, delivered = messages(runs[0].stdout, "CAM")
        extra = cpu - base_cpu
        per = 1e6 * extra / delivered if delivered else float("nan")
        print(f"{name:<44} {wall:10.2f} s {cpu:9.2f} s {extra:8.2f} s {sent:10d} {delivered:11d} {per:16.3f}")
    peak = summary_value(results["sbsim (no services)"][0].stdout, "peak running")
    print(f"\npeak running: {peak:.0f} vehicles")


if __name__ == "__main__":
    main()
