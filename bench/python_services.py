"""Cost of services written in Python (storyboard.services) against the same services in C++, on bench1k's
1,000 running vehicles (from a state saved at 100 s), with the disc model and the channel model:

- a beacon-and-count service: sbsim's C++ `Beacon` against a Python beacon (schedule_after, send, and an
  indicate() per reception counting them); the traces of a short window must be byte-identical (checked);
- a service reading every CAM (CaService sends them): a C++ CamStatsService (tests/python/plugins/services,
  built here against this build's SDK) against the same in Python reading the CAMs in batches
  (indicate_batch, numpy columns per trigger) and one on_cam() call per CAM; their statistics must agree.

It prints CPU seconds (user + system: the machine is shared) as medians of interleaved runs, the ratios to the
C++ runs, and the µs of CPU each Python callback adds (the difference over the number of callbacks).

    SBSIM_EXECUTABLE=build/dev/sbsim PYTHONPATH=python .venv/bin/python bench/python_services.py [--end 3] [--runs 3]
"""

from __future__ import annotations

import argparse
import hashlib
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import pandas as pd
from benchlib import ROOT, Window, alternate, median, sbsim

PY_BEACON = """
from storyboard.services import Service


class PyBeacon(Service):
    attributes = {"interval": float, "bytes": int}

    def initialize(self):
        self.interval = self.attribute("interval", 0.1)
        self.bytes = self.attribute("bytes", 190)
        self.heard = 0
        self.schedule_after(self.start_phase(self.interval), self.beacon)

    def beacon(self):
        self.send("Beacon", self.bytes, security="cam")
        self.schedule_after(self.interval, self.beacon)

    def indicate(self, message):
        self.heard += 1

    def finish(self):
        self.record_scalar("heard", self.heard)
"""

PY_CAM_STATS = """
import numpy as np
from storyboard.services import Service


class Stats(Service):
    def initialize(self):
        self.cams = 0
        self.slow = 0
        self.speed_sum = 0.0

    def finish(self):
        self.record_scalar("cams", self.cams)
        self.record_scalar("slow", self.slow)
        self.record_scalar("speed_sum", self.speed_sum)


class CamStatsBatch(Stats):
    def indicate_batch(self, messages):
        speeds = messages.cam_speeds
        speeds = speeds[~np.isnan(speeds)]
        self.cams += len(speeds)
        self.slow += int(np.count_nonzero(speeds < 1.0))
        self.speed_sum += float(speeds.sum())


class CamStatsEach(Stats):
    def on_cam(self, cam):
        speed = cam.speed
        self.cams += 1
        if speed < 1.0:
            self.slow += 1
        self.speed_sum += speed
"""


def services(folder: Path, name: str, *entries: str) -> Path:
    path = folder / f"{name}.xml"
    path.write_text("<services>\n" + "\n".join(f"  {e}" for e in entries) + "\n</services>\n", encoding="utf-8")
    return path


def build_plugin(folder: Path) -> Path:
    """tests/python/plugins/services against the SDK of the sbsim measured (installed from its build folder)."""
    build = Path(sbsim()).resolve().parent
    sdk, out = folder / "sdk", folder / "plugin"
    for cmd in (
        ["cmake", "--install", str(build), "--prefix", str(sdk)],
        ["cmake", "-S", str(ROOT / "tests/python/plugins/services"), "-B", str(out), f"-DCMAKE_PREFIX_PATH={sdk}"],
        ["cmake", "--build", str(out), "-j2"],
    ):
        done = subprocess.run(cmd, capture_output=True, text=True, check=False)
        if done.returncode != 0:
            sys.exit(f"{' '.join(cmd)} failed:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}")
    return out / "libtest_services.so"


def delivered(stdout: str, kind: str) -> tuple[int, int]:
    for line in stdout.splitlines():
        if line.startswith(f"messages {kind}: sent "):
            sent, got = line.split(": sent ")[1].split(", delivered ")
            return int(sent), int(got)
    return 0, 0


def same_trace(window: Window, radio: list[str], cpp: Path, py: Path, folder: Path) -> int:
    """Runs both beacons over the window's first 0.5 s with --messages (a few million lines); exits unless the
    traces are byte-identical. Returns their line count."""
    short = Window(window.preset, 0.5, window.step, window.state_at)
    digests, lines = [], 0
    for name, file in (("cpp", cpp), ("py", py)):
        trace = folder / f"{name}.jsonl"
        cmd = short.sbsim_command(sbsim(), "--services", str(file), "--messages", str(trace), "--quiet", *radio)
        subprocess.run(cmd, check=True, capture_output=True)
        digest = hashlib.sha256()
        with trace.open("rb") as f:
            for block in iter(lambda: f.read(1 << 20), b""):
                digest.update(block)
                lines += block.count(b"\n") if name == "cpp" else 0
        digests.append(digest.hexdigest())
        trace.unlink()
    if digests[0] != digests[1]:
        sys.exit("the Python beacon's trace differs from the C++ Beacon's")
    return lines


def agree(folder: Path, names: list[str]) -> None:
    """The CAM readers' scalars are the same: counts exactly, speed sums to rounding."""
    tables = [pd.read_parquet(folder / f"{n}.parquet").query("name in ['cams', 'slow', 'speed_sum']") for n in names]
    first = tables[0].pivot_table(index="vehicle", columns="name", values="value", aggfunc="sum")
    for name, table in zip(names[1:], tables[1:], strict=True):
        other = table.pivot_table(index="vehicle", columns="name", values="value", aggfunc="sum")
        if not (first[["cams", "slow"]].equals(other[["cams", "slow"]])):
            sys.exit(f"{name}: CAM counts differ from the C++ service's")
        if ((first["speed_sum"] - other["speed_sum"]).abs() > 1e-6 * first["speed_sum"].abs().clip(lower=1)).any():
            sys.exit(f"{name}: CAM speed sums differ from the C++ service's")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--end", type=float, default=3.0, help="simulated seconds after the state (default 3)")
    parser.add_argument("--runs", type=int, default=3, help="runs per command (default 3)")
    parser.add_argument("--radio", choices=["disc", "channel", "both"], default="both")
    args = parser.parse_args()

    window = Window("bench1k", args.end, state_at=100.0)
    radios = {"disc": [], "channel": ["--radio", str(ROOT / "bench" / "radio.toml")]}
    chosen = list(radios) if args.radio == "both" else [args.radio]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        (folder / "pybeacon.py").write_text(PY_BEACON, encoding="utf-8")
        (folder / "camstats.py").write_text(PY_CAM_STATS, encoding="utf-8")
        plugin = build_plugin(folder)
        cpp_beacon = services(folder, "cpp_beacon", '<service type="Beacon"/>')
        py_beacon = services(folder, "py_beacon", '<service type="python:pybeacon.py:PyBeacon"/>')
        readers = {
            "CaService + C++ CamStats": services(
                folder, "cam_cpp", '<service type="CaService"/>', '<service type="CamStatsService"/>'
            ),
            "CaService + Python batch": services(
                folder, "cam_batch", '<service type="CaService"/>', '<service type="python:camstats.py:CamStatsBatch"/>'
            ),
            "CaService + Python on_cam": services(
                folder, "cam_each", '<service type="CaService"/>', '<service type="python:camstats.py:CamStatsEach"/>'
            ),
        }
        for radio in chosen:
            lines = same_trace(window, radios[radio], cpp_beacon, py_beacon, folder)
            print(f"{radio}: the Python beacon's trace equals the C++ Beacon's ({lines:,} lines, 0.5 s)", flush=True)
            base = ["--threads", "1", "--plugin", str(plugin), *radios[radio]]
            commands = {
                "C++ Beacon": window.sbsim_command(sbsim(), *base, "--services", str(cpp_beacon)),
                "Python beacon": window.sbsim_command(sbsim(), *base, "--services", str(py_beacon)),
            }
            for name, file in readers.items():
                stats = folder / f"{radio}-{file.stem}.parquet"
                commands[name] = window.sbsim_command(
                    sbsim(), *base, "--services", str(file), "--statistics", str(stats)
                )
            print(f"{radio}: {window.describe()}, {args.runs} runs each, interleaved, one thread", flush=True)
            results = alternate(commands, args.runs)
            agree(folder, [f"{radio}-{readers[n].stem}" for n in readers])
            cpu = {n: median([r.cpu for r in runs]) for n, runs in results.items()}
            wall = {n: median([r.wall for r in runs]) for n, runs in results.items()}
            sent, got = delivered(results["Python beacon"][0].stdout, "Beacon")
            _, cams = delivered(results["CaService + C++ CamStats"][0].stdout, "CAM")
            rows.append((radio, "C++ Beacon", wall, cpu, "C++ Beacon", None))
            rows.append((radio, "Python beacon", wall, cpu, "C++ Beacon", (sent + got, "sends + receptions")))
            rows.append((radio, "CaService + C++ CamStats", wall, cpu, "CaService + C++ CamStats", None))
            rows.append((radio, "CaService + Python batch", wall, cpu, "CaService + C++ CamStats", None))
            rows.append((radio, "CaService + Python on_cam", wall, cpu, "CaService + C++ CamStats", (cams, "CAMs")))

    print(
        "\n| radio | service | median wall s | median CPU s | CPU ratio | wall/CPU | µs CPU per Python callback |\n"
        "|---|---|---:|---:|---:|---:|---:|"
    )
    for radio, name, wall, cpu, against, callbacks in rows:
        ratio = cpu[name] / cpu[against]
        per = ""
        if callbacks:
            count, what = callbacks
            per = f"{1e6 * (cpu[name] - cpu[against]) / count:.2f} ({count:,} {what})"
        print(
            f"| {radio} | {name} | {wall[name]:.2f} | {cpu[name]:.2f} | {ratio:.2f}× | {wall[name] / cpu[name]:.2f} |"
            f" {per} |"
        )


if __name__ == "__main__":
    os.environ.setdefault("PYTHONPATH", str(ROOT / "python"))
    main()
