"""Runs a few radio scenarios with two sbsim executables and compares their message traces
(--messages) byte for byte: the channel model with several radio files (path-loss models, fading,
extra delays, a small queue) and the disc model, on the bundled stories. A change that must not
alter what the radio does shows it here (event logs: tools/compare_logs.py):

    .venv/bin/python tools/compare_traces.py BEFORE_EXECUTABLE AFTER_EXECUTABLE [--threads 2] [--end 45]

Exit 0 when every trace is identical, 1 otherwise; prints one line per run with the SHA-256 and
the trace's line count.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
STORIES = ROOT / "stories"


@dataclass(frozen=True)
class Case:
    """One run: a bundled story, a radio file's text (None: the disc model) and extra arguments."""

    name: str
    story: str
    radio: str | None
    extra: list[str] = field(default_factory=list)


CASES = [
    Case("accident-defaults", "motorway-accident", "", ["--messages-range", "800"]),
    Case(
        "accident-log-nakagami",
        "motorway-accident",
        '[propagation]\npath_loss = "log-distance"\nexponent = 2.2\nfading = "nakagami"\nnakagami_m = 1\n'
        '[latency]\ndelay_model = "gamma"\ndelay_s = 0.002\n[mac]\nqueue_limit = 1\ncontention_window = 3\n',
    ),
    Case(
        "police-two-ray-veins",
        "highway-police",
        '[phy]\npower_dbm = 20\nrate_mbps = 12\n[propagation]\npath_loss = "two-ray-ground"\n'
        'fading = "nakagami-veins"\n[latency]\ndelay_model = "uniform"\ndelay_min_s = 0.001\ndelay_max_s = 0.003\n'
        "[performance]\nlinks_per_chunk = 16\n",
    ),
    Case(
        "police-free-space",
        "highway-police",
        '[propagation]\npath_loss = "free-space"\nshadowing_sigma_db = 6\n[latency]\ndelay_model = "constant"\n'
        "delay_s = 0.001\n",
        ["--param", "radio_power_dbm=15"],
    ),
    Case("accident-disc", "motorway-accident", None, ["--v2x-fade-start", "300", "--messages-range", "800"]),
    Case("police-disc", "highway-police", None, ["--v2x-range", "300"]),
]


def story_arguments(directory: Path) -> list[str]:
    """The command line that runs one bundled story as it is."""
    args = ["--sumocfg", str(next(directory.glob("*.sumocfg"))), "--story", str(directory / "story.py")]
    if (directory / "services.xml").exists():
        args += ["--services", str(directory / "services.xml")]
    return args


def story_environment() -> dict[str, str]:
    """The environment of a run: the stories import this checkout's `storyboard` package."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(ROOT / "python"), env.get("PYTHONPATH", "")) if p)
    return env


def trace_digest(executable: str, case: Case, end: float, threads: int) -> tuple[str, int]:
    """The trace's SHA-256 and line count, or ("exit N", 0) when the run failed."""
    with tempfile.TemporaryDirectory() as tmp:
        messages = Path(tmp) / "messages.jsonl"
        args = [*story_arguments(STORIES / case.story), *case.extra]
        if case.radio is not None:
            radio = Path(tmp) / "radio.toml"
            radio.write_text(case.radio)
            args += ["--radio", str(radio)]
        command = [executable, *args, "--end", str(end), "--threads", str(threads), "--quiet"]
        run = subprocess.run([*command, "--messages", str(messages)], check=False, env=story_environment())
        if run.returncode != 0:
            return f"exit {run.returncode}", 0
        data = messages.read_bytes()
        return hashlib.sha256(data).hexdigest(), data.count(b"\n")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--end", type=float, default=45.0, help="simulated seconds per run (default 45)")
    parser.add_argument("--threads", type=int, default=1, help="--threads of both runs (default 1)")
    parser.add_argument("--only", default=None, help="run only the cases whose name contains this")
    options = parser.parse_args()
    same = True
    for case in CASES:
        if options.only is not None and options.only not in case.name:
            continue
        before, lines = trace_digest(options.before, case, options.end, options.threads)
        after, _ = trace_digest(options.after, case, options.end, options.threads)
        same = same and before == after and not before.startswith("exit")
        verdict = "identical" if before == after else "DIFFERENT"
        print(f"{case.name:24} {verdict} {before[:16]} {after[:16]} {lines} lines", flush=True)
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
