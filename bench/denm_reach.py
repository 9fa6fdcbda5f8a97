"""DENM reach with and without GeoNetworking forwarding, on stories/motorway-accident: the crash
car's DENM goes to a 1,000 m circle; how far from the crash do stations take it in, on the disc
model (500 m) and, with --radio, on the 802.11p channel model too.

For each medium and `--gn-forwarding on|off`: DENM frames sent and forwarded; the first DENM (40 s):
the stations inside the area then, how many took it within 0.5 s and the farthest of them; over the
run: stations warned and the farthest distance from the crash at which one took a DENM in (its
`denm` `new` line, its position from SUMO's FCD at that step).

    .venv/bin/python bench/denm_reach.py [--end 170] [--radio bench/radio.toml]
"""

from __future__ import annotations

import argparse
import bisect
import math
import tempfile
from pathlib import Path

from benchlib import ROOT, sbsim, timed
from sbsim.fcd import read_timesteps
from sbsim.messages import read_message_lines

SCENARIO = ROOT / "stories" / "motorway-accident"
AREA = 1000.0  # den-use-cases.xml: area="1000"
STEP = 0.5  # motorway.sumocfg


def measure(out: Path, forwarding: str, end: float, radio: Path | None) -> dict[str, float]:
    messages, fcd = out / f"m-{forwarding}.jsonl", out / f"fcd-{forwarding}.xml"
    cmd = [
        sbsim(),
        "--quiet",
        "--story",
        str(SCENARIO / "story.py"),
        "--sumocfg",
        str(SCENARIO / "motorway.sumocfg"),
        "--services",
        str(SCENARIO / "services.xml"),
        "--messages",
        str(messages),
        "--end",
        repr(end),
        "--gn-forwarding",
        forwarding,
        "--sumo-option",
        f"--fcd-output {fcd}",
    ]
    if radio is not None:
        cmd += ["--radio", str(radio)]
    run = timed(cmd)
    lines = read_message_lines(messages)
    positions = {s.t: {v.vehicle: (v.x, v.y) for v in s.vehicles} for s in read_timesteps(fcd, STEP)}
    times = sorted(positions)

    def where(station: str, t: float) -> tuple[float, float] | None:
        # The first FCD state at or after t: the step whose positions the reception saw.
        for ts in times[bisect.bisect_left(times, t - 1e-9) :][:3]:
            if station in positions[ts]:
                return positions[ts][station]
        return None

    tx = [line for line in lines if line["event"] == "tx" and line["type"] == "DENM"]
    crash = next(line for line in tx if line["station"] == "crash")
    centre, t0 = (crash["x"], crash["y"]), crash["t"]
    new = [line for line in lines if line["event"] == "denm" and line["phase"] == "new" and line["station"] != "crash"]
    reach, first = [], []
    for line in new:
        p = where(line["station"], line["t"])
        if p is None:
            continue  # a roadside unit, or a vehicle that left in that step
        d = math.dist(p, centre)
        reach.append(d)
        if line["t"] <= t0 + 0.5:
            first.append(d)
    state = positions[min(times, key=lambda x: abs(x - t0))]
    inside = sum(1 for v, p in state.items() if v != "crash" and math.dist(p, centre) <= AREA)
    return {
        "sent": sum(line["station"] == "crash" and line.get("hops", 1) == 1 for line in tx),
        "forwarded": sum(line.get("hops", 1) > 1 for line in tx),
        "inside": inside,
        "first": len(first),
        "first_far": max(first, default=0.0),
        "warned": len(reach),
        "far": max(reach, default=0.0),
        "cpu": run.cpu,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--end", type=float, default=170.0, help="simulated seconds (default 170: the whole event)")
    parser.add_argument("--radio", type=Path, help="also on the 802.11p channel model with this radio file")
    args = parser.parse_args()
    media: list[tuple[str, Path | None]] = [("disc 500 m", None)]
    if args.radio is not None:
        media.append((f"channel ({args.radio.name})", args.radio))
    print(
        "| medium | forwarding | DENMs sent | forwarded | first DENM: stations in area | took it within 0.5 s "
        "| farthest (m) | warned over the run | farthest (m) | CPU (s) |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for name, radio in media:
            for forwarding in ("off", "on"):
                f = measure(Path(tmp), forwarding, args.end, radio)
                print(
                    f"| {name} | {forwarding} | {f['sent']:.0f} | {f['forwarded']:.0f} | {f['inside']:.0f} "
                    f"| {f['first']:.0f} | {f['first_far']:.0f} | {f['warned']:.0f} | {f['far']:.0f} "
                    f"| {f['cpu']:.1f} |",
                    flush=True,
                )


if __name__ == "__main__":
    main()
