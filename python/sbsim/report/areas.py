"""Where stories act, from the story script: ``sbsim check --json`` lists each story's areas.

The event log and the summary carry neither areas nor positions, and the script needs sbsim's
compiled module to load, so the report asks the program (the one :func:`sbsim.runner.executable`
finds) to load the script without running it.
"""

from __future__ import annotations

import json
import os
import subprocess
from collections.abc import Sequence
from dataclasses import dataclass

from sbsim import runner
from sbsim.report.loading import ReportError


@dataclass(frozen=True)
class Area:
    """One area of a story, in SUMO's frame, as ``sbsim check --json`` reports it: a polygon's vertices
    (not closed), or with ``radius`` a circle around ``points[0]``."""

    story: str
    condition: str
    points: tuple[tuple[float, float], ...]
    radius: float | None = None


#: How long ``sbsim check`` may take (it loads SUMO's network and the script, and runs nothing).
CHECK_TIMEOUT_S = 300.0


def story_areas(
    story: str | os.PathLike[str], sumocfg: str | os.PathLike[str], params: Sequence[str] = ()
) -> dict[str, list[Area]]:
    """Each story of the script (in registration order) with its areas, from ``sbsim check --json``.

    ``params`` are ``NAME=VALUE`` strings passed as ``--param`` (a script may place its areas by
    them). Raises :class:`ReportError` when sbsim is missing or rejects the script or scenario."""
    extra = [arg for param in params for arg in ("--param", param)]
    try:
        done = runner.run(sumocfg, story=story, extra=[*extra, "check", "--json"], timeout=CHECK_TIMEOUT_S)
    except OSError as e:  # no sbsim found (runner.executable), or one that does not start
        raise ReportError(f"{e.filename or 'sbsim'}: {e.strerror or e}") from e
    except subprocess.TimeoutExpired as e:
        raise ReportError(f"{story}: sbsim check took more than {CHECK_TIMEOUT_S:g} s") from e
    # 1 would be warnings under --strict, which is not asked for: anything but 0 is a failure.
    if done.returncode != 0:
        raise ReportError(f"{story}: sbsim check failed (exit {done.returncode}): {_check_error(done.stderr)}")
    try:
        document = json.loads(done.stdout)
        return {
            entry["name"]: [
                Area(
                    entry["name"],
                    area["condition"],
                    tuple((float(x), float(y)) for x, y in area["points"]),
                    float(area["radius"]) if "radius" in area else None,
                )
                for area in entry["areas"]
            ]
            for entry in document["stories"]
        }
    except (json.JSONDecodeError, KeyError, TypeError, ValueError) as e:
        raise ReportError(f"{story}: sbsim check --json printed no story areas ({e!r}); is sbsim older?") from e


def _check_error(stderr: str) -> str:
    """The line of sbsim's stderr that says what is wrong: its last own ``sbsim: ...`` line (a script's
    error comes after Python's traceback), else the last line."""
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    own = [line.removeprefix("sbsim: ") for line in lines if line.startswith("sbsim: ")]
    return own[-1] if own else lines[-1] if lines else "no message"
