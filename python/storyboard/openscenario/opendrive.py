"""The little of an OpenDRIVE file a RoadPosition needs: which lane a lateral offset `t` from the
road's reference line falls in, at `s`, from the lane sections and their width polynomials."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from .errors import ScenarioError, read_xml


def _last_at(records: Any, key: str, at: float) -> Any:
    """Of records that start at their attribute `key`, the last one starting at or before `at` (or None)."""
    chosen = None
    for record in sorted(records, key=lambda r: float(r.get(key, "0"))):
        if float(record.get(key, "0")) <= at + 1e-9:
            chosen = record
    return chosen


def _width(lane: Any, ds: float) -> float:
    chosen = _last_at(lane.iterfind("width"), "sOffset", ds)
    if chosen is None:
        return 0.0
    d = ds - float(chosen.get("sOffset", "0"))
    a, b, c, e = (float(chosen.get(k, "0")) for k in ("a", "b", "c", "d"))
    return a + b * d + c * d * d + e * d * d * d


def lane_at(xodr: Path, road: str, s: float, t: float, what: str) -> int:
    """The OpenDRIVE lane id (negative: right of the reference line) holding offset `t` at `s`."""
    root = read_xml(xodr, f"the OpenDRIVE file of {what}")
    element = next((r for r in root.iterfind("road") if r.get("id") == road), None)
    if element is None:
        raise ScenarioError(f"{what}: {xodr.name} has no road '{road}'")
    offsets = element.findall("lanes/laneOffset")
    if any(float(o.get(k, "0")) != 0 for o in offsets for k in ("a", "b", "c", "d")):
        raise ScenarioError(f"{what}: road '{road}' has a laneOffset, which RoadPosition does not follow")
    section = _last_at(element.iterfind("lanes/laneSection"), "s", s)
    if section is None:
        raise ScenarioError(f"{what}: road '{road}' has no lane section at s={s:g}")
    ds = s - float(section.get("s", "0"))
    side = "right" if t < 0 else "left"
    lanes = sorted(section.iterfind(f"{side}/lane"), key=lambda lane: abs(int(lane.get("id", "0"))))
    edge = 0.0
    for lane in lanes:
        edge += _width(lane, ds)
        if abs(t) <= edge + 1e-9:
            return int(lane.get("id", "0"))
    raise ScenarioError(f"{what}: t={t:g} is off road '{road}' at s={s:g} ({edge:g} m of lanes on the {side})")
