"""The SUMO network a scenario plays on, and OpenSCENARIO positions on it.

Positions map to SUMO lanes so: on a network netconvert made from OpenDRIVE (`--opendrive-files`
with `--output.original-names`), each lane's `origId` parameter names its OpenDRIVE road and lane
(`"<road>_<lane>"`), and `s` runs along the road's edges in order (right lanes, negative ids, in
the road's direction; left lanes against it). On another SUMO network `roadId` is a SUMO edge and
`laneId` counts OpenDRIVE's way: -1 the lane next to the centre line (SUMO's leftmost), -2 the one
right of it, ...; a `laneId` >= 0 is SUMO's lane index (0: the rightmost)."""

from __future__ import annotations

import math
import os
import shutil
import subprocess
from dataclasses import dataclass, field
from pathlib import Path

from .errors import ScenarioError, read_xml


@dataclass
class Lane:
    id: str
    edge: str
    index: int
    length: float
    shape: list[tuple[float, float]]
    orig: list[str]  # OpenDRIVE "<road>_<lane>" ids this lane came from


@dataclass
class TrafficLight:
    """A SUMO traffic light (tlLogic) as the network file has it: its first programme."""

    id: str
    links: int  # letters of its state: the links it controls
    phases: list[tuple[str, str]]  # (name, state) in programme order; name "" if none


@dataclass
class Network:
    path: Path
    offset: tuple[float, float] = (0.0, 0.0)  # netconvert's netOffset: SUMO = OpenDRIVE + offset
    lanes: dict[str, Lane] = field(default_factory=dict)
    edges: dict[str, list[Lane]] = field(default_factory=dict)  # lanes by index
    successors: dict[str, list[tuple[str, str]]] = field(default_factory=dict)  # lane -> (lane, dir)
    speed_limits: dict[str, float] = field(default_factory=dict)  # lane -> m/s
    lights: dict[str, TrafficLight] = field(default_factory=dict)  # SUMO traffic light id -> light
    # OpenDRIVE signal id -> (SUMO traffic light, its link indices): netconvert's linkSignalID params
    signals: dict[str, tuple[str, list[int]]] = field(default_factory=dict)

    @classmethod
    def read(cls, path: Path) -> Network:
        net = cls(path)
        root = read_xml(path, "the SUMO network")
        location = root.find("location")
        if location is not None and location.get("netOffset"):
            x, y = location.get("netOffset", "0,0").split(",")
            net.offset = (float(x), float(y))
        for edge in root.iterfind("edge"):
            if edge.get("function") == "internal":
                continue
            lanes = []
            for lane in edge.iterfind("lane"):
                orig = [p.get("value", "") for p in lane.iterfind("param") if p.get("key") == "origId"]
                shape = [tuple(float(v) for v in point.split(",")[:2]) for point in lane.get("shape", "").split()]
                entry = Lane(
                    lane.get("id", ""),
                    edge.get("id", ""),
                    int(lane.get("index", "0")),
                    float(lane.get("length", "0")),
                    [(p[0], p[1]) for p in shape],
                    " ".join(orig).split(),
                )
                net.lanes[entry.id] = entry
                net.speed_limits[entry.id] = float(lane.get("speed", "13.89"))
                lanes.append(entry)
            net.edges[edge.get("id", "")] = sorted(lanes, key=lambda lane: lane.index)
        for logic in root.iterfind("tlLogic"):
            tls = logic.get("id", "")
            if tls in net.lights:
                continue  # another programme of the same light: its links are the same
            phases = [(p.get("name", ""), p.get("state", "")) for p in logic.iterfind("phase")]
            net.lights[tls] = TrafficLight(tls, len(phases[0][1]) if phases else 0, phases)
            for param in logic.iterfind("param"):
                key = param.get("key", "")
                if key.startswith("linkSignalID:"):
                    signal = net.signals.setdefault(param.get("value", ""), (tls, []))
                    if signal[0] == tls:
                        signal[1].append(int(key.split(":", 1)[1]))
        for c in root.iterfind("connection"):
            src, dst = c.get("from", ""), c.get("to", "")
            if src not in net.edges or dst not in net.edges:
                continue
            from_lane = f"{src}_{c.get('fromLane')}"
            net.successors.setdefault(from_lane, []).append((f"{dst}_{c.get('toLane')}", c.get("dir", "s")))
        return net

    def lane_position(self, road: str, lane_id: int, s: float, what: str) -> tuple[Lane, float]:
        """The SUMO lane and position of OpenDRIVE road/lane/s (see the module's doc)."""
        key = f"{road}_{lane_id}"
        converted = [lane for lane in self.lanes.values() if key in lane.orig]
        if converted:
            # One road may be several edges (lane sections): walk them in the driving direction.
            forward = lane_id < 0
            converted.sort(key=lambda lane: _section_start(lane.edge), reverse=not forward)
            total = sum(lane.length for lane in converted)
            along = s if forward else total - s
            if along < -1e-6 or along > total + 1e-6:
                raise ScenarioError(f"{what}: road {road} lane {lane_id} s={s:g} is off the road (length {total:g} m)")
            for lane in converted:
                if along <= lane.length + 1e-6:
                    return lane, max(0.0, min(along, lane.length))
                along -= lane.length
            return converted[-1], converted[-1].length
        lanes = self.edges.get(road)
        if lanes is None:
            raise ScenarioError(
                f"{what}: road '{road}' lane {lane_id} maps to no SUMO lane "
                f"(no lane has origId '{key}' and no edge is named '{road}' in {self.path})"
            )
        index = lane_id if lane_id >= 0 else len(lanes) + lane_id
        if not 0 <= index < len(lanes):
            raise ScenarioError(f"{what}: edge '{road}' has {len(lanes)} lanes, no lane {lane_id}")
        lane = lanes[index]
        if s < 0 or s > lane.length + 1e-6:
            raise ScenarioError(f"{what}: s={s:g} is off edge '{road}' (length {lane.length:g} m)")
        return lane, min(s, lane.length)

    def lane_index(self, lane_id: int, what: str) -> int:
        """SUMO's lane index (from the right) of OpenDRIVE lane `lane_id` (an AbsoluteTargetLane,
        which names no road): the one index every road's lane of that id converted to, or on a SUMO
        network the index (>= 0) or the lane counted from the left (< 0) on edges alike."""
        suffix = f"_{lane_id}"
        converted = {lane.index for lane in self.lanes.values() if any(o.endswith(suffix) for o in lane.orig)}
        if not converted:
            counts = {len(lanes) for lanes in self.edges.values()}
            converted = {lane_id if lane_id >= 0 else n + lane_id for n in counts}
            if any(i < 0 or i >= n for i in converted for n in counts):
                raise ScenarioError(f"{what}: lane {lane_id} is not on every edge of {self.path}")
        if len(converted) != 1:
            raise ScenarioError(
                f"{what}: lane {lane_id} is SUMO lane {' or '.join(map(str, sorted(converted)))} depending on the "
                f"road; an AbsoluteTargetLane needs one (use a RelativeTargetLane)"
            )
        return converted.pop()

    def world_position(self, x: float, y: float, what: str) -> tuple[Lane, float]:
        """The lane nearest to OpenDRIVE world point (x, y) (within 10 m), and the position on it."""
        px, py = x + self.offset[0], y + self.offset[1]
        best: tuple[float, Lane, float] | None = None
        for lane in self.lanes.values():
            d, pos = _project(lane.shape, px, py)
            if best is None or d < best[0]:
                best = (d, lane, pos)
        if best is None or best[0] > 10.0:
            raise ScenarioError(f"{what}: world position ({x:g}, {y:g}) is on no SUMO lane (none within 10 m)")
        return best[1], best[2]

    def xy(self, lane: Lane, pos: float) -> tuple[float, float]:
        """SUMO coordinates of the point `pos` m along `lane`."""
        remaining = pos
        for (x0, y0), (x1, y1) in zip(lane.shape, lane.shape[1:], strict=False):
            seg = math.hypot(x1 - x0, y1 - y0)
            if remaining <= seg or seg == 0:
                f = 0.0 if seg == 0 else remaining / seg
                return (x0 + f * (x1 - x0), y0 + f * (y1 - y0))
            remaining -= seg
        return lane.shape[-1]

    def follow(self, lane: Lane, limit: int = 200) -> list[str]:
        """The edges a vehicle on `lane` passes keeping straight on (its lane's way), from its own."""
        edges = [lane.edge]
        current = lane.id
        for _ in range(limit):
            nexts = self.successors.get(current, [])
            if not nexts:
                break
            straight = [n for n in nexts if n[1] == "s"] or nexts
            current = straight[0][0]
            edge = self.lanes[current].edge
            if edge in edges:
                break
            edges.append(edge)
        return edges


def _section_start(edge: str) -> float:
    # netconvert names the edges of later lane sections "<road>.<s>"; the first has no suffix.
    tail = edge.rsplit(".", 1)
    try:
        return float(tail[1]) if len(tail) == 2 else 0.0
    except ValueError:
        return 0.0


def _project(shape: list[tuple[float, float]], px: float, py: float) -> tuple[float, float]:
    best = (math.inf, 0.0)
    along = 0.0
    for (x0, y0), (x1, y1) in zip(shape, shape[1:], strict=False):
        dx, dy = x1 - x0, y1 - y0
        seg2 = dx * dx + dy * dy
        f = 0.0 if seg2 == 0 else max(0.0, min(1.0, ((px - x0) * dx + (py - y0) * dy) / seg2))
        d = math.hypot(px - (x0 + f * dx), py - (y0 + f * dy))
        if d < best[0]:
            best = (d, along + f * math.sqrt(seg2))
        along += math.sqrt(seg2)
    return best


def sumo_binary(name: str) -> str:
    """A SUMO tool of the installed eclipse-sumo wheel (else from PATH)."""
    try:
        import sumo  # noqa: PLC0415 - the wheel is a dependency, but keep the import local

        candidate = Path(sumo.SUMO_HOME) / "bin" / name
        if candidate.exists():
            return str(candidate)
    except ImportError:
        pass
    found = shutil.which(name)
    if found is None:
        raise ScenarioError(f"{name}: not found (install eclipse-sumo)")
    return found


def convert_opendrive(xodr: Path, cache: Path) -> tuple[Path, list[str]]:
    """The SUMO network of `xodr`, converted once into `cache` (again when the .xodr is newer)."""
    net = cache / f"{xodr.stem}.net.xml"
    command = [
        sumo_binary("netconvert"),
        "--opendrive-files",
        str(xodr),
        "--output.original-names",
        "--no-warnings",
        "-o",
        str(net),
    ]
    if net.exists() and net.stat().st_mtime >= xodr.stat().st_mtime:
        return net, command
    cache.mkdir(parents=True, exist_ok=True)
    # Written under another name and renamed: runs of a study may convert the same file at once.
    partial = cache / f".{net.name}.{os.getpid()}"
    result = subprocess.run([*command[:-1], str(partial)], capture_output=True, text=True, check=False)
    if result.returncode != 0:
        partial.unlink(missing_ok=True)
        lines = [line for line in result.stderr.splitlines() if line.strip() and "SUMO_HOME" not in line]
        raise ScenarioError(f"{xodr}: netconvert failed: {lines[-1] if lines else result.returncode}")
    partial.replace(net)
    return net, command
