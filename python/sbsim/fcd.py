"""SUMO's FCD output (``--sumo-option "--fcd-output f.xml"``), read once and put in sbsim's time.

SUMO labels an FCD state with the time at the start of its step, sbsim the time after it, so FCD
time ``T`` is sbsim time ``T + step``. The step is given, or the FCD's own spacing, or a fallback
(the sumocfg's ``step-length``, else 1 s) when the file has a single time step.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["FcdError", "Timestep", "VehicleState", "read_fcd", "read_timesteps"]


class FcdError(ValueError):
    """A file that is not usable FCD output: ``path[:line]: what is wrong``."""


class VehicleState(NamedTuple):
    """One vehicle in one time step (``lane`` and ``type`` None where the FCD leaves them out; a tuple,
    not a dataclass, because an FCD holds millions of them)."""

    vehicle: str
    x: float
    y: float
    speed: float
    lane: str | None
    type: str | None


class Timestep(NamedTuple):
    """The vehicles SUMO reported after one step, at sbsim time ``t`` (rounded to 1 ms, as sbsim's log)."""

    t: float
    vehicles: tuple[VehicleState, ...]


def read_timesteps(
    path: str | os.PathLike[str], step: float | None = None, fallback_step: float = 1.0
) -> list[Timestep]:
    """Every ``<timestep>`` of the file in order, empty ones too, with its ``<vehicle>`` states.

    Raises :class:`FcdError` for a file that is not FCD output, broken XML or a state that is not
    numeric, and :class:`OSError` for one that cannot be read."""
    raw: list[tuple[float, tuple[VehicleState, ...]]] = []
    root_seen = False
    try:
        for event, element in ET.iterparse(os.fspath(path), events=("start", "end")):
            if event == "start":
                if not root_seen and element.tag != "fcd-export":
                    raise FcdError(f"{os.fspath(path)}: not SUMO FCD output (no <fcd-export>)")
                root_seen = True
            elif element.tag == "timestep":
                raw.append((_number(path, element, "time"), tuple(_state(path, v) for v in element.iter("vehicle"))))
                element.clear()  # keeps memory flat on long runs
    except ET.ParseError as e:
        if not root_seen:
            raise FcdError(f"{os.fspath(path)}: not SUMO FCD output (not XML: {e})") from e
        line = e.position[0] if e.position else "?"
        raise FcdError(f"{os.fspath(path)}:{line}: bad XML: {e}") from e
    if step is None:
        spacing = [b - a for (a, _), (b, _) in zip(raw, raw[1:], strict=False) if b > a]
        step = min(spacing) if spacing else fallback_step
    return [Timestep(round(t + step, 3), vehicles) for t, vehicles in raw]


def read_fcd(path: str | os.PathLike[str], step: float | None = None, fallback_step: float = 1.0) -> pd.DataFrame:
    """The vehicle states as columns ``t`` (sbsim time), ``vehicle``, ``x``, ``y``, ``speed``, one row each
    (errors as :func:`read_timesteps`)."""
    import pandas as pd

    rows = [(s.t, v.vehicle, v.x, v.y, v.speed) for s in read_timesteps(path, step, fallback_step) for v in s.vehicles]
    return pd.DataFrame(rows, columns=["t", "vehicle", "x", "y", "speed"])


def _state(path: str | os.PathLike[str], vehicle: ET.Element) -> VehicleState:
    a = vehicle.attrib
    try:
        return VehicleState(a["id"], float(a["x"]), float(a["y"]), float(a["speed"]), a.get("lane"), a.get("type"))
    except (KeyError, ValueError):
        for key in ("x", "y", "speed"):
            _number(path, vehicle, key)  # raises, naming the attribute
        raise FcdError(f"{os.fspath(path)}: a <vehicle> has no id") from None


def _number(path: str | os.PathLike[str], element: ET.Element, key: str) -> float:
    text = element.get(key)
    try:
        return float(text)  # type: ignore[arg-type]  # None: a TypeError, reported below
    except (TypeError, ValueError) as e:
        what = f"<{element.tag}{' ' + element.get('id', '') if element.tag == 'vehicle' else ''}>"
        problem = f"has no '{key}'" if text is None else f"'{key}' is not numeric ({text!r})"
        raise FcdError(f"{os.fspath(path)}: {what} {problem}") from e
