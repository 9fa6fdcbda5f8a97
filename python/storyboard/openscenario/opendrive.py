"""The little of an OpenDRIVE file a RoadPosition needs: which lane a lateral offset `t` from the
road's reference line falls in, at `s`, from the lane sections and their width polynomials."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from lxml import etree

from .errors import ScenarioError


def _width(lane: Any, ds: float) -> float:
    records = sorted(lane.iterfind("width"), key=lambda w: float(w.get("sOffset", "0")))
    chosen = None
    for w in records:
        if float(w.get("sOffset", "0")) <= ds + 1e-9:
            chosen = w
    if chosen is None:
        return 0.0
    d = ds - float(chosen.get("sOffset", "0"))
    a, b, c, e = (float(chosen.get(k, "0")) for k in ("a", "b", "c", "d"))
    return a + b * d + c * d * d + e * d * d * d


def lane_at(xodr: Path, road: str, s: float, t: float, what: str) -> int:
    """The OpenDRIVE lane id (negative: right of the reference line) holding offset `t` at `s`."""
    try:
        root = etree.parse(str(xodr)).getroot()
    except (OSError, etree.XMLSyntaxError) as e:
        raise ScenarioError(f"{what}: cannot read {xodr}: {e}") from None
    element = next((r for r in root.iterfind("road") if r.get("id") == road), None)
    if element is None:
        raise ScenarioError(f"{what}: {xodr.name} has no road '{road}'")
    offsets = element.findall("lanes/laneOffset")
    if any(float(o.get(k, "0")) != 0 for o in offsets for k in ("a", "b", "c", "d")):
        raise ScenarioError(f"{what}: road '{road}' has a laneOffset, which RoadPosition does not follow")
    sections = sorted(element.iterfind("lanes/laneSection"), key=lambda x: float(x.get("s", "0")))
    section = None
    for candidate in sections:
        if float(candidate.get("s", "0")) <= s + 1e-9:
            section = candidate
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
