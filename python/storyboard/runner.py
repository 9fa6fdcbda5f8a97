"""Run the ``sbsim`` program from Python and read what it writes."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import sysconfig
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any


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
        """The final summary's ``key: value`` lines."""
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


class EventLogError(ValueError):
    """A line of an event log that is not an event: ``path:line: what is wrong``."""

    def __init__(self, path: str | os.PathLike[str], line: int, message: str) -> None:
        super().__init__(f"{os.fspath(path)}:{line}: {message}")
        self.path = os.fspath(path)
        self.line = line


#: What every event carries, whatever its type (sbsim writes them first on each line).
EVENT_FIELDS: dict[str, type | tuple[type, ...]] = {"t": (int, float), "type": str, "story": str, "vehicle": str}
#: Event types a WorldStory writes with ``"vehicle": null`` (it acts on the network, not on a vehicle).
WORLD_EVENT_TYPES = ("activate", "deactivate")


def read_events(path: str | os.PathLike[str]) -> list[dict[str, Any]]:
    """The events of an ``--events`` file, one dict per line (``pandas.read_json(path, lines=True)`` works too).

    Raises :class:`EventLogError` (naming the line) for a line that is not a JSON object with ``t``,
    ``type``, ``story`` and ``vehicle`` (``None`` in a WorldStory's activate and deactivate lines);
    blank lines are skipped.
    """
    events: list[dict[str, Any]] = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, start=1):
            if not line.strip():
                continue
            try:
                event = json.loads(line)
            except json.JSONDecodeError as e:
                raise EventLogError(path, number, f"bad JSON: {e.msg} (column {e.colno})") from e
            if not isinstance(event, dict):
                raise EventLogError(path, number, "not a JSON object")
            for key, kind in EVENT_FIELDS.items():
                if key == "vehicle" and key in event and event[key] is None and event.get("type") in WORLD_EVENT_TYPES:
                    continue
                # bool is an int to isinstance, but never a time.
                if not isinstance(event.get(key), kind) or isinstance(event.get(key), bool):
                    raise EventLogError(path, number, f"'{key}' missing or not a {_kind_name(kind)}")
            events.append(event)
    return events


#: What every line of a message trace (``--messages``) carries, by its ``event``.
MESSAGE_FIELDS: dict[str, dict[str, type | tuple[type, ...]]] = {
    "tx": {
        "t": (int, float),
        "type": str,
        "station": str,
        "seq": int,
        "bytes": int,
        "x": (int, float),
        "y": (int, float),
    },
    "rx": {"t": (int, float), "type": str, "station": str, "sender": str, "seq": int, "distance": (int, float)},
    "lost": {"t": (int, float), "type": str, "station": str, "sender": str, "seq": int, "reason": str},
}


def read_messages(path: str | os.PathLike[str]) -> list[dict[str, Any]]:
    """The lines of a ``--messages`` trace, one dict per line, in time order: ``tx`` per transmission,
    ``rx`` per reception, ``lost`` per lost reception within the radio's trace range (``reason``:
    sensing, propagation, collision, half-duplex, queue; the disc model: range, fade).

    Raises :class:`EventLogError` (naming the line) for a line that is not such an object.
    """
    lines: list[dict[str, Any]] = []
    with open(path, encoding="utf-8") as f:
        for number, text in enumerate(f, start=1):
            if not text.strip():
                continue
            try:
                line = json.loads(text)
            except json.JSONDecodeError as e:
                raise EventLogError(path, number, f"bad JSON: {e.msg} (column {e.colno})") from e
            if not isinstance(line, dict) or line.get("event") not in MESSAGE_FIELDS:
                raise EventLogError(path, number, "not a message trace line (event tx, rx or lost)")
            for key, kind in MESSAGE_FIELDS[line["event"]].items():
                if not isinstance(line.get(key), kind) or isinstance(line.get(key), bool):
                    raise EventLogError(path, number, f"'{key}' missing or not a {_kind_name(kind)}")
            lines.append(line)
    return lines


def _kind_name(kind: type | tuple[type, ...]) -> str:
    return "number" if isinstance(kind, tuple) else "string"


def read_summary(path: str | os.PathLike[str]) -> dict[str, Any]:
    """The run's ``--summary`` JSON document (machine-readable; the text summary on stdout is for people)."""
    with open(path, encoding="utf-8") as f:
        data: dict[str, Any] = json.load(f)
    return data


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m storyboard.runner --cmake-prefix`` prints :func:`cmake_prefix`."""
    import argparse

    parser = argparse.ArgumentParser(prog="python -m storyboard.runner", description=main.__doc__)
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
