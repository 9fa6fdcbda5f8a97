"""Run the ``sbsim`` program from Python: find it, run it, and read what it writes.

The outputs have their own readers, re-exported here: :func:`read_events` (:mod:`sbsim.events`) and
:func:`read_summary` (:mod:`sbsim.summary`).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import sysconfig
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from sbsim.events import EVENT_FIELDS, WORLD_EVENT_TYPES, EventLogError, read_events
from sbsim.messages import MESSAGE_FIELDS, read_message_lines, read_messages
from sbsim.summary import SummaryError, read_summary

__all__ = [
    "EVENT_FIELDS",
    "WORLD_EVENT_TYPES",
    "EventLogError",
    "MESSAGE_FIELDS",
    "RunResult",
    "SummaryError",
    "cmake_prefix",
    "executable",
    "main",
    "read_events",
    "read_message_lines",
    "read_messages",
    "read_summary",
    "run",
]


def executable() -> Path:
    """``$SBSIM_EXECUTABLE`` if set, else the ``sbsim`` beside this Python (its ``bin/``), else ``PATH``'s."""
    override = os.environ.get("SBSIM_EXECUTABLE")
    if override:
        return Path(override)
    beside = Path(sys.prefix) / "bin" / "sbsim"
    if beside.is_file() and os.access(beside, os.X_OK):
        return beside
    found = shutil.which("sbsim")
    if found is None:
        raise FileNotFoundError("sbsim is not installed: run ./sbsim once, or pip install .")
    return Path(found)


@dataclass(frozen=True)
class RunResult:
    returncode: int
    stdout: str
    stderr: str

    def summary(self) -> dict[str, str]:
        """The final summary's ``key: value`` lines (the text for people; :func:`read_summary` reads
        the ``--summary`` JSON)."""
        out: dict[str, str] = {}
        for line in self.stdout.splitlines():
            key, sep, value = line.partition(": ")
            if sep and not key.startswith("sbsim "):
                out[key] = value
        return out


def run(
    sumocfg: str | os.PathLike[str] | None = None,
    *,
    story: str | os.PathLike[str] | None = None,
    events: str | os.PathLike[str] | None = None,
    end: float | None = None,
    seed: int | None = None,
    sumo_options: Sequence[str] = (),
    quiet: bool = False,
    extra: Sequence[str] = (),
    timeout: float | None = None,
) -> RunResult:
    """Runs ``sbsim`` with these options and returns its exit code and output (never raises on failure)."""
    args: list[str] = [str(executable())]
    if sumocfg is not None:
        args += ["--sumocfg", os.fspath(sumocfg)]
    if story is not None:
        args += ["--story", os.fspath(story)]
    if events is not None:
        args += ["--events", os.fspath(events)]
    if end is not None:
        args += ["--end", repr(end)]
    if seed is not None:
        args += ["--seed", str(seed)]
    for option in sumo_options:
        args += ["--sumo-option", option]
    if quiet:
        args.append("--quiet")
    args += list(extra)
    done = subprocess.run(args, capture_output=True, text=True, timeout=timeout, check=False)
    return RunResult(done.returncode, done.stdout, done.stderr)


def cmake_prefix() -> Path:
    """Where pip put sbsim's C++ SDK (libsbsim, headers, the CMake package): pass it to CMake as
    ``-DCMAKE_PREFIX_PATH`` so that ``find_package(sbsim)`` works for out-of-tree service modules."""
    return Path(sysconfig.get_paths()["platlib"]) / "sbsim"


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m sbsim.runner --cmake-prefix`` prints :func:`cmake_prefix`."""
    import argparse

    parser = argparse.ArgumentParser(prog="python -m sbsim.runner", description=main.__doc__)
    parser.add_argument(
        "--cmake-prefix", action="store_true", help="print the CMAKE_PREFIX_PATH for find_package(sbsim)"
    )
    args = parser.parse_args(argv)
    if args.cmake_prefix:
        print(cmake_prefix())
    else:
        parser.print_help()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
