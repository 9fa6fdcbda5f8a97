"""Runs every scenario in stories/ with two sbsim executables and compares the event logs byte for
byte (a change that must not alter behaviour, e.g. a speed-up, shows it here):

    .venv/bin/python tools/compare_logs.py BEFORE_EXECUTABLE AFTER_EXECUTABLE [--end 300]

Exit 0 when every log is identical, 1 otherwise; prints one line per scenario with the SHA-256.
"""

from __future__ import annotations

import argparse
import hashlib
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def scenario_arguments(directory: Path) -> list[str]:
    """The command line that runs one bundled scenario as it is."""
    args = ["--sumocfg", str(next(directory.glob("*.sumocfg"))), "--story", str(directory / "story.py")]
    if (directory / "services.xml").exists():
        args += ["--services", str(directory / "services.xml")]
    return args


def events_digest(executable: str, args: list[str], end: float | None) -> str:
    """The event log's SHA-256, or "exit N" when the run failed (e.g. an older build lacks a feature)."""
    with tempfile.TemporaryDirectory() as tmp:
        events = Path(tmp) / "events.jsonl"
        extra = ["--end", str(end)] if end is not None else []
        run = subprocess.run([executable, *args, *extra, "--quiet", "--events", str(events)], check=False)
        if run.returncode != 0:
            return f"exit {run.returncode}"
        return hashlib.sha256(events.read_bytes()).hexdigest()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--end", type=float, default=None, help="simulated seconds (default: each sumocfg's end)")
    options = parser.parse_args()
    same = True
    for directory in sorted(p for p in (ROOT / "stories").iterdir() if p.is_dir()):
        args = scenario_arguments(directory)
        before = events_digest(options.before, args, options.end)
        after = events_digest(options.after, args, options.end)
        same = same and before == after
        print(f"{directory.name:18} {'identical' if before == after else 'DIFFERENT'} {before[:16]} {after[:16]}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
