"""The message trace at scale (issue 29): a CA run on bench1k's ~1,000 vehicles (the disc model, 500 m)
with a roadside unit announcing an event by DENM every second over the grid's centre, traced three ways:
Parquet with only DENMs (``--messages-types DENM``), Parquet with every line but lost ones and a budget
(``--messages-max-bytes``), and the same as JSON Lines. Prints each run's wall and CPU time, the file's
size, where the budget stopped the trace, and how long ``sbsim.messages.read_messages`` (pandas) takes to
read the file back.

    .venv/bin/python bench/trace.py [--preset bench1k] [--end 120] [--budget 200M]
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from pathlib import Path

from benchlib import sbsim, scenario, timed
from sbsim.messages import read_messages

SERVICES = """<services>
    <service type="CaService"/>
    <rsu id="rsu0" x="{x}" y="{y}">
        <service type="RsuDenService" cause="3" subcause="0" from="10" until="1e6" interval="1" area="600"/>
    </rsu>
</services>"""


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--preset", default="bench1k", help="make_grid preset (default bench1k)")
    parser.add_argument("--end", type=float, default=120.0, help="simulated seconds (default 120)")
    parser.add_argument("--budget", default="200M", help="--messages-max-bytes of the unfiltered runs (200M)")
    parser.add_argument("--no-jsonl", action="store_true", help="skip the JSON Lines run")
    args = parser.parse_args()

    cfg = scenario(args.preset)
    with tempfile.TemporaryDirectory(dir=cfg.parent) as tmp:
        out = Path(tmp)
        # The grid's junctions are 200 m apart from (0, 0): the unit sits near its middle.
        (out / "services.xml").write_text(SERVICES.format(x=500, y=500))
        base = [sbsim(), "--sumocfg", str(cfg), "--end", repr(args.end), "--services", str(out / "services.xml")]
        runs = {
            "parquet, --messages-types DENM": ("denm.parquet", ["--messages-types", "DENM"]),
            f"parquet, all but lost, budget {args.budget}": ("all.parquet", ["--messages-max-bytes", args.budget]),
        }
        if not args.no_jsonl:
            runs[f"jsonl, all but lost, budget {args.budget}"] = ("all.jsonl", ["--messages-max-bytes", args.budget])
        print(f"{args.preset}, {args.end:g} s simulated, CaService on every vehicle, one RSU DENM a second")
        for name, (file, extra) in runs.items():
            path, summary = out / file, out / f"{file}.summary.json"
            run = timed([*base, "--messages", str(path), "--summary", str(summary), *extra])
            trace = json.loads(summary.read_text())["message_trace"]
            counts = json.loads(summary.read_text())["messages"]
            sent = ", ".join(f"{kind} {figures['sent']:,}" for kind, figures in counts.items())
            start = time.perf_counter()
            lines = len(read_messages(path))
            read_all = time.perf_counter() - start
            start = time.perf_counter()
            read_messages(path, columns=["t", "station"], filters=[("event", "==", "rx"), ("type", "==", "DENM")])
            read_denm = time.perf_counter() - start
            stopped = f"truncated at t={trace['truncated_at']:g} s" if trace["truncated"] else "whole"
            print(
                # No peak RSS: a run started after a large read inherits this process's pages until it
                # execs, and wait4 counts them (measure sbsim's own with /usr/bin/time instead).
                f"{name}: wall {run.wall:.1f} s, cpu {run.cpu:.1f} s; "
                f"{path.stat().st_size / 1e6:.1f} MB, {lines:,} lines ({stopped}); "
                f"read_messages all {read_all:.2f} s, DENM rx (2 columns) {read_denm:.2f} s; "
                f"sent {sent}",
                flush=True,
            )


if __name__ == "__main__":
    main()
