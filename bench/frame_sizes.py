"""The channel busy ratio before and after frames got their real size (issue 27, part 4), on the
Sepulcre highway of bench/radio.py (5 km, 3 lanes each way, β = 0.06 vehicles/m at 25 m/s) with
every vehicle running Artery's CaService (EN 302 637-2 generation rules) on the channel model:

- before: a CAM's content plus 30 bytes of MAC, airtime at the rate without whole symbols (the
  reference build of main before the change, --before);
- after, unsecured: GeoNetworking, BTP, LLC/SNAP, the 802.11 QoS header and FCS around the CAM
  (`[frame] security = "none"`), whole OFDM symbols;
- after, signed: plus the TS 103 097 envelope (certificate once a second, digest otherwise).

Both builds draw shadowing afresh per frame (`shadowing_correlation_m = 0` for the new one), so
the frame size is the only difference. Printed: CAMs sent, the mean frame on the air, the mean and
largest channel busy ratio (sbsim's summary: every station's 100 ms samples).

    PYTHONPATH=python:tools .venv/bin/python bench/frame_sizes.py \\
        --before /work/ref/build/dev/sbsim --after build/dev/sbsim [--seconds 10] [--seed 23423]
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from radio import CONFIGS, make_highway  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent


def run(binary: str, cfg: Path, services: Path, radio: Path, seconds: float, seed: int, out: Path) -> dict:
    summary = out / "summary.json"
    messages = out / "messages.jsonl"
    cmd = [
        binary,
        "--sumocfg",
        str(cfg),
        "--end",
        f"{seconds:g}",
        "--services",
        str(services),
        "--radio",
        str(radio),
        "--param",
        "radio_trace_range=0",
        "--summary",
        str(summary),
        "--messages",
        str(messages),
        "--seed",
        str(seed),
        "--threads",
        "2",
        "--quiet",
    ]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"sbsim failed ({done.returncode}): {' '.join(cmd)}\n{done.stderr[-2000:]}")
    data = json.loads(summary.read_text())
    frames = total = 0
    with messages.open() as trace:
        for line in trace:
            e = json.loads(line)
            if e["event"] == "tx":
                frames += 1
                # Before the change a frame was its content and 30 bytes of MAC.
                total += e.get("frame_bytes", e["bytes"] + 30)
    messages.unlink()
    return {
        "sent": data["messages"]["CAM"]["sent"],
        "mean_frame_bytes": total / frames if frames else 0.0,
        "cbr_mean": data["channel_busy_ratio"]["mean"],
        "cbr_max": data["channel_busy_ratio"]["max"],
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--before", required=True, help="sbsim built before the change (main at 37e12be)")
    parser.add_argument("--after", required=True, help="sbsim with real frame sizes")
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--seed", type=int, default=23423)
    args = parser.parse_args()

    work = Path(tempfile.mkdtemp(prefix="frame-sizes-"))
    cfg = make_highway(ROOT / "bench" / "out" / "sepulcre", CONFIGS["base"])
    services = work / "ca.services.xml"
    services.write_text('<services><service type="artery.application.CaService"/></services>\n')
    defaults = work / "before.toml"
    defaults.write_text("# the channel model's defaults\n")
    unsecured = work / "unsecured.toml"
    unsecured.write_text('[propagation]\nshadowing_correlation_m = 0\n[frame]\nsecurity = "none"\n')
    signed = work / "signed.toml"
    signed.write_text("[propagation]\nshadowing_correlation_m = 0\n")
    rows = {
        "before: content + 30 bytes": (args.before, defaults),
        "after: headers, no security": (args.after, unsecured),
        "after: headers and signature": (args.after, signed),
    }
    print(
        f"CaService on every vehicle of the Sepulcre highway ({round(CONFIGS['base'].density * 5000)} vehicles), "
        f"{args.seconds:g} s, seed {args.seed}, channel model defaults"
    )
    print(f"{'frames':<32} {'CAMs sent':>10} {'mean frame B':>13} {'CBR mean':>9} {'CBR max':>8}")
    for name, (binary, radio) in rows.items():
        r = run(binary, cfg, services, radio, args.seconds, args.seed, work)
        print(f"{name:<32} {r['sent']:>10} {r['mean_frame_bytes']:>13.1f} {r['cbr_mean']:>9.4f} {r['cbr_max']:>8.4f}")


if __name__ == "__main__":
    main()
