#!/usr/bin/env python3
"""Generate small, deterministic SUMO grid scenarios for sbsim.

The scenario is written into one folder:

* ``net.net.xml``      -- a ``grid x grid`` network built by ``netgenerate``
* ``routes.rou.xml``   -- vehicle types ``car`` and ``truck`` plus vehicles
* ``<name>.sumocfg``   -- SUMO configuration using relative paths

Two traffic models are available:

``trips``
    Random origin/destination trips from ``randomTrips.py`` (routed with
    ``duarouter``), one vehicle every ``period`` seconds from ``begin`` to
    ``end``.  Vehicles arrive and leave the simulation; good for stories.

``loops``
    ``vehicles`` vehicles, inserted evenly during the first ``ramp`` seconds,
    each driving a random rectangular loop around a block of the grid with
    ``repeat`` set so that it never arrives before ``end``.  The number of
    running vehicles therefore stays constant at ``vehicles`` after the ramp,
    which is what the benchmarks need.

Everything is seeded: the same arguments give byte-identical files and SUMO
runs that produce identical outputs.  The SUMO binaries are located through
the ``sumo`` Python package (``eclipse-sumo`` wheel) of the interpreter that
runs this script.

Examples::

    python tools/make_grid.py OUT_DIR --preset bench5k
    python tools/make_grid.py OUT_DIR --grid 4 --end 200 --seed 1
    python tools/make_grid.py --list-presets

Library use (with ``tools/`` on ``sys.path``)::

    from make_grid import make_grid, make_preset
    cfg = make_grid(tmp_path, grid=4, end=200.0, seed=1)
    bench_cfg = make_preset(tmp_path / "b", "bench5k")
"""

from __future__ import annotations

import argparse
import dataclasses
import importlib
import math
import os
import random
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Literal, get_args

TrafficMode = Literal["trips", "loops"]
TlsType = Literal["static", "actuated", "delay_based"]
JunctionType = Literal["traffic_light", "priority", "right_before_left", "allway_stop", "priority_stop"]

NET_FILE = "net.net.xml"
ROUTE_FILE = "routes.rou.xml"

#: Upper bound of SUMO's default ``speedFactor`` distribution (normc(1, 0.1, 0.2, 2)).
_MAX_SPEED_FACTOR = 2.0


@dataclass(frozen=True)
class VehicleType:
    """A SUMO ``<vType>``; values are constants tests can check per vehicle."""

    id: str
    vclass: str
    length: float
    width: float
    height: float
    max_speed: float
    accel: float
    decel: float
    min_gap: float
    color: str

    def element(self) -> ET.Element:
        return ET.Element(
            "vType",
            {
                "id": self.id,
                "vClass": self.vclass,
                "length": _num(self.length),
                "width": _num(self.width),
                "height": _num(self.height),
                "maxSpeed": _num(self.max_speed),
                "accel": _num(self.accel),
                "decel": _num(self.decel),
                "minGap": _num(self.min_gap),
                "color": self.color,
            },
        )


CAR = VehicleType(
    id="car",
    vclass="passenger",
    length=4.5,
    width=1.8,
    height=1.5,
    max_speed=50.0,
    accel=2.6,
    decel=4.5,
    min_gap=2.5,
    color="1,1,0",
)
TRUCK = VehicleType(
    id="truck",
    vclass="truck",
    length=12.0,
    width=2.5,
    height=3.4,
    max_speed=25.0,
    accel=1.3,
    decel=4.0,
    min_gap=2.5,
    color="0.2,0.4,1",
)
VEHICLE_TYPES: tuple[VehicleType, ...] = (CAR, TRUCK)


@dataclass(frozen=True)
class GridConfig:
    """All parameters of a generated scenario (see :func:`make_grid`)."""

    name: str = "grid"
    grid: int = 5
    spacing: float = 200.0
    lanes: int = 1
    speed: float = 13.89
    junction: JunctionType = "traffic_light"
    tls_type: TlsType = "static"
    begin: float = 0.0
    end: float = 300.0
    step_length: float = 1.0
    seed: int = 42
    traffic: TrafficMode = "trips"
    period: float = 1.0
    min_distance: float | None = None
    vehicles: int = 1000
    ramp: float = 100.0
    truck_share: float = 0.2
    time_to_teleport: float = 120.0
    ignore_junction_blocker: float = 30.0
    quiet: bool = True
    #: Written into the .sumocfg as is (comma-separated, relative to it); not generated.
    additional_files: str = ""

    def validate(self) -> None:
        if self.grid < 2:
            raise ValueError("grid must be >= 2")
        if self.spacing <= 0 or self.speed <= 0 or self.step_length <= 0:
            raise ValueError("spacing, speed and step_length must be > 0")
        if self.lanes < 1:
            raise ValueError("lanes must be >= 1")
        if self.end <= self.begin:
            raise ValueError("end must be > begin")
        if self.traffic not in get_args(TrafficMode):
            raise ValueError(f"unknown traffic mode {self.traffic!r}")
        if self.junction not in get_args(JunctionType):
            raise ValueError(f"unknown junction type {self.junction!r}")
        if self.tls_type not in get_args(TlsType):
            raise ValueError(f"unknown traffic light type {self.tls_type!r}")
        if self.traffic == "trips" and self.period <= 0:
            raise ValueError("period must be > 0")
        if self.traffic == "loops" and self.vehicles < 1:
            raise ValueError("vehicles must be >= 1")
        if not 0.0 <= self.truck_share <= 1.0:
            raise ValueError("truck_share must be within [0, 1]")
        if not re.fullmatch(r"[A-Za-z0-9_.-]+", self.name):
            raise ValueError(f"bad scenario name {self.name!r}")


def _bench(vehicles: int, grid: int) -> GridConfig:
    return GridConfig(
        name=f"bench{vehicles // 1000}k",
        grid=grid,
        spacing=200.0,
        lanes=2,
        tls_type="actuated",
        end=3600.0,
        traffic="loops",
        vehicles=vehicles,
        ramp=100.0,
        seed=42,
    )


_GRID_RAIN = GridConfig(
    name="grid-rain",
    grid=6,
    spacing=200.0,
    lanes=1,
    end=600.0,
    traffic="trips",
    period=1.5,
    min_distance=600.0,
    seed=42,
)

#: Named scenarios.  The ``benchN`` presets keep about one vehicle per 45-50 m
#: of lane, so the load per vehicle stays similar from 1,000 to 20,000
#: vehicles; all ``vehicles`` are inserted during the first 100 s and then stay
#: running.  ``end`` (3600 s) sizes the loop repetitions, so no vehicle arrives
#: before it; a benchmark may stop earlier with ``--end``.
PRESETS: dict[str, GridConfig] = {
    "grid-rain": _GRID_RAIN,
    # stories/weather-front: grid-rain's grid, other trips; front.poly.xml (hand-written, beside
    # the .sumocfg) holds the front's polygon.
    "weather-front": dataclasses.replace(_GRID_RAIN, name="weather-front", seed=7, additional_files="front.poly.xml"),
    "bench1k": _bench(1_000, 6),
    "bench2k": _bench(2_000, 8),
    "bench5k": _bench(5_000, 13),
    "bench10k": _bench(10_000, 18),
    "bench20k": _bench(20_000, 25),
    # bench/soak.py: 80 minutes of random trips; with the soak stories slowing them, about 2,200
    # running once the first 20 minutes have filled the grid, ~4 arrivals and departures a second.
    "soak": GridConfig(
        name="soak",
        grid=12,
        spacing=200.0,
        lanes=2,
        end=4800.0,
        traffic="trips",
        period=0.25,
        min_distance=1200.0,
        seed=7,
    ),
}


# --------------------------------------------------------------------------- #
# SUMO installation
# --------------------------------------------------------------------------- #


def sumo_home() -> Path:
    """SUMO_HOME of the ``eclipse-sumo`` package of the running interpreter."""
    try:
        sumo = importlib.import_module("sumo")
    except ImportError as exc:  # pragma: no cover - environment problem
        raise RuntimeError("the 'sumo' package is missing; pip install eclipse-sumo") from exc
    return Path(str(sumo.SUMO_HOME))


def sumo_binary(name: str) -> Path:
    """Path of a SUMO binary such as ``sumo`` or ``netgenerate``."""
    exe = name + (".exe" if os.name == "nt" else "")
    path = sumo_home() / "bin" / exe
    if not path.exists():
        raise FileNotFoundError(path)
    return path


def _sumo_env() -> dict[str, str]:
    env = dict(os.environ)
    env["SUMO_HOME"] = str(sumo_home())
    return env


def _run(cmd: Sequence[str | Path], cwd: Path) -> None:
    proc = subprocess.run(
        [str(c) for c in cmd],
        cwd=cwd,
        env=_sumo_env(),
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        check=False,
    )
    if proc.returncode != 0:
        raise RuntimeError(f"command failed ({proc.returncode}): {' '.join(map(str, cmd))}\n{proc.stdout}")


# --------------------------------------------------------------------------- #
# helpers
# --------------------------------------------------------------------------- #


def _num(value: float) -> str:
    """Short, stable text for a number (``1`` instead of ``1.0``)."""
    if float(value).is_integer():
        return str(int(value))
    return f"{value:.6g}" if abs(value) < 1e6 else f"{value:.2f}"


def _write_xml(path: Path, root: ET.Element, comment: str | None = None) -> None:
    ET.indent(root, space="    ")
    body = ET.tostring(root, encoding="unicode")
    head = '<?xml version="1.0" encoding="UTF-8"?>\n'
    if comment:
        head += f"<!-- {comment} -->\n"
    path.write_text(head + body + "\n", encoding="utf-8")


def _describe(cfg: GridConfig) -> str:
    # An empty field added later is left out, so older scenarios regenerate identical files.
    fields = " ".join(
        f"{f.name}={getattr(cfg, f.name)}"
        for f in dataclasses.fields(cfg)
        if not (f.name == "additional_files" and not cfg.additional_files)
    )
    return f"generated by sbsim tools/make_grid.py: {fields}"


_HEADER_RE = re.compile(r"<!-- generated on \S+ by ")


def _strip_timestamp(path: Path) -> None:
    """Drop the generation time from SUMO's header so files are reproducible."""
    text = path.read_text(encoding="utf-8")
    path.write_text(_HEADER_RE.sub("<!-- generated by ", text, count=1), "utf-8")


@dataclass(frozen=True)
class _GridNet:
    """Grid topology parsed from the generated network."""

    node: dict[tuple[int, int], str]  # (column, row) -> junction id
    edge: dict[tuple[str, str], str]  # (from junction, to junction) -> edge id
    length: dict[str, float]  # edge id -> length [m]
    columns: int
    rows: int


def _parse_grid(net_file: Path) -> _GridNet:
    root = ET.parse(net_file).getroot()
    coords: dict[str, tuple[float, float]] = {}
    for junction in root.iter("junction"):
        if junction.get("type") == "internal":
            continue
        coords[junction.attrib["id"]] = (
            float(junction.attrib["x"]),
            float(junction.attrib["y"]),
        )
    xs = sorted({round(x, 2) for x, _ in coords.values()})
    ys = sorted({round(y, 2) for _, y in coords.values()})
    node = {(xs.index(round(x, 2)), ys.index(round(y, 2))): jid for jid, (x, y) in coords.items()}
    edge: dict[tuple[str, str], str] = {}
    length: dict[str, float] = {}
    for e in root.iter("edge"):
        if e.get("function") == "internal":
            continue
        eid = e.attrib["id"]
        edge[(e.attrib["from"], e.attrib["to"])] = eid
        lane = e.find("lane")
        length[eid] = float(lane.attrib["length"]) if lane is not None else 0.0
    return _GridNet(node=node, edge=edge, length=length, columns=len(xs), rows=len(ys))


def _corner_junctions(net_file: Path) -> list[str]:
    g = _parse_grid(net_file)
    corners = [(0, 0), (g.columns - 1, 0), (0, g.rows - 1), (g.columns - 1, g.rows - 1)]
    return [g.node[c] for c in corners if c in g.node]


# --------------------------------------------------------------------------- #
# network
# --------------------------------------------------------------------------- #


def _netgenerate(out_dir: Path, cfg: GridConfig, tls_unset: Sequence[str]) -> None:
    cmd: list[str | Path] = [
        sumo_binary("netgenerate"),
        "--grid",
        "--grid.number",
        str(cfg.grid),
        "--grid.length",
        _num(cfg.spacing),
        "--default.lanenumber",
        str(cfg.lanes),
        "--default.speed",
        _num(cfg.speed),
        "--default.junctions.type",
        cfg.junction,
        "--tls.default-type",
        cfg.tls_type,
        "--no-turnarounds",
        "--seed",
        str(cfg.seed),
        "--output-file",
        NET_FILE,
    ]
    if tls_unset:
        cmd += ["--tls.unset", ",".join(tls_unset)]
    _run(cmd, cwd=out_dir)


def _make_net(out_dir: Path, cfg: GridConfig) -> None:
    _netgenerate(out_dir, cfg, ())
    if cfg.junction == "traffic_light":
        # Corners only join two roads; a traffic light there just stops traffic.
        _netgenerate(out_dir, cfg, _corner_junctions(out_dir / NET_FILE))
    _strip_timestamp(out_dir / NET_FILE)


# --------------------------------------------------------------------------- #
# traffic
# --------------------------------------------------------------------------- #


def _routes_root() -> ET.Element:
    root = ET.Element(
        "routes",
        {
            "xmlns:xsi": "http://www.w3.org/2001/XMLSchema-instance",
            "xsi:noNamespaceSchemaLocation": "http://sumo.dlr.de/xsd/routes_file.xsd",
        },
    )
    for vtype in VEHICLE_TYPES:
        root.append(vtype.element())
    return root


def _pick_type(rng: random.Random, truck_share: float) -> str:
    return TRUCK.id if rng.random() < truck_share else CAR.id


def _make_trips(out_dir: Path, cfg: GridConfig) -> None:
    """Random trips via randomTrips.py + duarouter, then typed by Python."""
    with tempfile.TemporaryDirectory(prefix="make_grid_") as tmp_name:
        tmp = Path(tmp_name)
        routed = tmp / "routed.rou.xml"
        cmd: list[str | Path] = [
            sys.executable,
            sumo_home() / "tools" / "randomTrips.py",
            "--net-file",
            (out_dir / NET_FILE).resolve(),
            "--output-trip-file",
            tmp / "trips.trips.xml",
            "--route-file",
            routed,
            "--seed",
            str(cfg.seed),
            "--begin",
            _num(cfg.begin),
            "--end",
            _num(cfg.end),
            "--period",
            _num(cfg.period),
            "--prefix",
            "veh",
            "--threads",
            "1",
        ]
        if cfg.min_distance:
            cmd += ["--min-distance", _num(cfg.min_distance)]
        _run(cmd, cwd=tmp)
        vehicles = ET.parse(routed).getroot().findall("vehicle")

    rng = random.Random(cfg.seed)
    root = _routes_root()
    for vehicle in vehicles:
        route = vehicle.find("route")
        if route is None:
            continue
        root.append(
            _vehicle(
                vehicle.attrib["id"],
                _pick_type(rng, cfg.truck_share),
                float(vehicle.attrib["depart"]),
                route.attrib["edges"].split(),
                repeat=0,
                depart_pos="base",
            )
        )
    _write_xml(out_dir / ROUTE_FILE, root, _describe(cfg))


def _vehicle(
    vid: str,
    vtype: str,
    depart: float,
    edges: Sequence[str],
    *,
    repeat: int,
    depart_pos: str,
) -> ET.Element:
    vehicle = ET.Element(
        "vehicle",
        {
            "id": vid,
            "type": vtype,
            "depart": f"{depart:.2f}",
            "departLane": "best",
            "departPos": depart_pos,
            "departSpeed": "max",
        },
    )
    route = ET.SubElement(vehicle, "route", {"edges": " ".join(edges)})
    if repeat > 0:
        route.set("repeat", str(repeat))
    return vehicle


def _rectangle(g: _GridNet, x0: int, x1: int, y0: int, y1: int, clockwise: bool) -> list[str]:
    nodes = (
        [(x, y0) for x in range(x0, x1)]
        + [(x1, y) for y in range(y0, y1)]
        + [(x, y1) for x in range(x1, x0, -1)]
        + [(x0, y) for y in range(y1, y0, -1)]
    )
    if clockwise:
        nodes.reverse()
    ids = [g.node[n] for n in nodes]
    return [g.edge[(a, b)] for a, b in zip(ids, ids[1:] + ids[:1], strict=True)]


def _make_loops(out_dir: Path, cfg: GridConfig) -> None:
    """``vehicles`` vehicles on endless rectangular loops (constant load)."""
    g = _parse_grid(out_dir / NET_FILE)
    rng = random.Random(cfg.seed)
    root = _routes_root()
    width = len(str(cfg.vehicles - 1))
    max_speed = cfg.speed * _MAX_SPEED_FACTOR
    for i in range(cfg.vehicles):
        x0, x1 = sorted(rng.sample(range(g.columns), 2))
        y0, y1 = sorted(rng.sample(range(g.rows), 2))
        loop = _rectangle(g, x0, x1, y0, y1, clockwise=rng.random() < 0.5)
        start = rng.randrange(len(loop))
        loop = loop[start:] + loop[:start]
        vtype = _pick_type(rng, cfg.truck_share)
        depart = cfg.begin + cfg.ramp * i / cfg.vehicles
        loop_length = sum(g.length[e] for e in loop)
        # Enough repetitions that no vehicle can arrive before cfg.end.
        repeat = math.ceil((cfg.end - depart) * max_speed / loop_length) + 1
        root.append(
            _vehicle(
                f"veh{i:0{width}d}",
                vtype,
                depart,
                loop,
                repeat=repeat,
                depart_pos="random_free",
            )
        )
    _write_xml(out_dir / ROUTE_FILE, root, _describe(cfg))


# --------------------------------------------------------------------------- #
# configuration
# --------------------------------------------------------------------------- #


def _write_sumocfg(out_dir: Path, cfg: GridConfig) -> Path:
    root = ET.Element(
        "configuration",
        {
            "xmlns:xsi": "http://www.w3.org/2001/XMLSchema-instance",
            "xsi:noNamespaceSchemaLocation": "http://sumo.dlr.de/xsd/sumoConfiguration.xsd",
        },
    )

    def section(name: str, options: Sequence[tuple[str, str]]) -> None:
        sec = ET.SubElement(root, name)
        for key, value in options:
            ET.SubElement(sec, key, {"value": value})

    inputs = [("net-file", NET_FILE), ("route-files", ROUTE_FILE)]
    if cfg.additional_files:
        inputs.append(("additional-files", cfg.additional_files))
    section("input", inputs)
    section(
        "time",
        [
            ("begin", _num(cfg.begin)),
            ("end", _num(cfg.end)),
            ("step-length", _num(cfg.step_length)),
        ],
    )
    section(
        "processing",
        [
            ("time-to-teleport", _num(cfg.time_to_teleport)),
            ("ignore-junction-blocker", _num(cfg.ignore_junction_blocker)),
        ],
    )
    section("random_number", [("seed", str(cfg.seed))])
    report = [("no-step-log", "true"), ("duration-log.disable", "true")]
    if cfg.quiet:
        # Schema validation needs SUMO_HOME; without it SUMO warns on every load.
        report = [
            ("no-warnings", "true"),
            *report,
            ("xml-validation", "never"),
            ("xml-validation.routes", "never"),
        ]
    section("report", report)

    path = out_dir / f"{cfg.name}.sumocfg"
    _write_xml(path, root, _describe(cfg))
    return path


# --------------------------------------------------------------------------- #
# public API
# --------------------------------------------------------------------------- #


def build(out_dir: Path | str, cfg: GridConfig) -> Path:
    """Write the scenario described by ``cfg``; return the ``.sumocfg`` path."""
    cfg.validate()
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    _make_net(out, cfg)
    if cfg.traffic == "trips":
        _make_trips(out, cfg)
    else:
        _make_loops(out, cfg)
    return _write_sumocfg(out, cfg)


def make_grid(
    out_dir: Path | str,
    *,
    name: str = "grid",
    grid: int = 5,
    spacing: float = 200.0,
    lanes: int = 1,
    speed: float = 13.89,
    junction: JunctionType = "traffic_light",
    tls_type: TlsType = "static",
    begin: float = 0.0,
    end: float = 300.0,
    step_length: float = 1.0,
    seed: int = 42,
    traffic: TrafficMode = "trips",
    period: float = 1.0,
    min_distance: float | None = None,
    vehicles: int = 1000,
    ramp: float = 100.0,
    truck_share: float = 0.2,
    time_to_teleport: float = 120.0,
    ignore_junction_blocker: float = 30.0,
    quiet: bool = True,
    additional_files: str = "",
) -> Path:
    """Generate a deterministic grid scenario in ``out_dir``.

    Args:
        out_dir: folder for ``net.net.xml``, ``routes.rou.xml`` and
            ``<name>.sumocfg`` (created if missing, files overwritten).
        name: base name of the ``.sumocfg``.
        grid: junctions per side (``grid x grid`` junctions).
        spacing: distance between neighbouring junctions [m].
        lanes: lanes per direction.
        speed: speed limit [m/s].
        junction: netgenerate junction type; with ``traffic_light`` the four
            corner junctions are left as priority junctions.
        tls_type: netgenerate ``tls.default-type``; ``actuated`` gives a
            steadier number of halting vehicles than fixed-time ``static``.
        begin, end: simulation interval written into the ``.sumocfg`` [s].
        step_length: simulation step length [s].
        seed: seed for netgenerate, randomTrips, the loop generator and SUMO.
        traffic: ``"trips"`` (random trips, one per ``period``) or ``"loops"``
            (``vehicles`` vehicles on endless loops, inserted during ``ramp``).
        period: insertion period of ``trips`` [s].
        min_distance: minimum straight-line trip distance for ``trips`` [m].
        vehicles: number of vehicles for ``loops``.
        ramp: insertion period for all ``loops`` vehicles [s].
        truck_share: probability that a vehicle gets vType ``truck``.
        time_to_teleport: SUMO ``time-to-teleport`` [s].
        ignore_junction_blocker: SUMO ``ignore-junction-blocker`` [s].
        quiet: write ``no-warnings`` and ``xml-validation=never`` into the
            configuration (validation needs SUMO_HOME and warns without it).
        additional_files: the ``.sumocfg``'s ``additional-files`` (comma-separated,
            relative to it), e.g. a polygon file written by hand; empty: none.

    Returns:
        Path of the written ``.sumocfg``.
    """
    cfg = GridConfig(
        name=name,
        grid=grid,
        spacing=spacing,
        lanes=lanes,
        speed=speed,
        junction=junction,
        tls_type=tls_type,
        begin=begin,
        end=end,
        step_length=step_length,
        seed=seed,
        traffic=traffic,
        period=period,
        min_distance=min_distance,
        vehicles=vehicles,
        ramp=ramp,
        truck_share=truck_share,
        time_to_teleport=time_to_teleport,
        ignore_junction_blocker=ignore_junction_blocker,
        quiet=quiet,
        additional_files=additional_files,
    )
    return build(out_dir, cfg)


def make_preset(out_dir: Path | str, preset: str, **overrides: object) -> Path:
    """Generate a named preset (see :data:`PRESETS`), optionally overridden."""
    try:
        cfg = PRESETS[preset]
    except KeyError:
        raise ValueError(f"unknown preset {preset!r}; choose from {', '.join(PRESETS)}") from None
    cfg = dataclasses.replace(cfg, **overrides)  # type: ignore[arg-type]
    return build(out_dir, cfg)


# --------------------------------------------------------------------------- #
# command line
# --------------------------------------------------------------------------- #


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0] if __doc__ else None,
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="presets: "
        + ", ".join(
            f"{k} ({v.grid}x{v.grid}, {v.lanes} lane(s), "
            + (f"{v.vehicles} loop vehicles" if v.traffic == "loops" else "trips")
            + ")"
            for k, v in PRESETS.items()
        ),
    )
    p.add_argument("out_dir", nargs="?", type=Path, help="output folder")
    p.add_argument("--preset", choices=sorted(PRESETS), help="start from a preset")
    p.add_argument("--list-presets", action="store_true", help="print presets")
    p.add_argument("--name", help="base name of the .sumocfg (default: grid)")
    p.add_argument("--grid", type=int, help="junctions per side (default 5)")
    p.add_argument("--spacing", type=float, help="junction distance [m] (200)")
    p.add_argument("--lanes", type=int, help="lanes per direction (1)")
    p.add_argument("--speed", type=float, help="speed limit [m/s] (13.89)")
    p.add_argument("--junction", choices=get_args(JunctionType), help="junction type")
    p.add_argument("--tls-type", choices=get_args(TlsType), help="TLS program")
    p.add_argument("--begin", type=float, help="begin time [s] (0)")
    p.add_argument("--end", type=float, help="end time [s] (300)")
    p.add_argument("--step-length", type=float, help="step length [s] (1)")
    p.add_argument("--seed", type=int, help="random seed (42)")
    p.add_argument("--traffic", choices=get_args(TrafficMode), help="traffic model")
    p.add_argument("--period", type=float, help="trips: insertion period [s] (1)")
    p.add_argument("--min-distance", type=float, help="trips: min distance [m]")
    p.add_argument("--vehicles", type=int, help="loops: number of vehicles")
    p.add_argument("--ramp", type=float, help="loops: insertion period [s] (100)")
    p.add_argument("--truck-share", type=float, help="share of trucks (0.2)")
    p.add_argument("--time-to-teleport", type=float, help="SUMO option (120)")
    p.add_argument("--ignore-junction-blocker", type=float, help="SUMO option [s] (30)")
    p.add_argument("--additional-files", help="written into the .sumocfg as is (comma-separated; none)")
    p.add_argument(
        "--warnings",
        dest="quiet",
        action="store_false",
        default=None,
        help="do not write no-warnings into the .sumocfg",
    )
    return p


def main(argv: Sequence[str] | None = None) -> int:
    parser = _parser()
    args = parser.parse_args(argv)
    if args.list_presets:
        for key, value in PRESETS.items():
            print(f"{key}: {value}")
        return 0
    if args.out_dir is None:
        parser.error("out_dir is required")
    cfg = PRESETS[args.preset] if args.preset else GridConfig()
    overrides = {
        f.name: getattr(args, f.name) for f in dataclasses.fields(GridConfig) if getattr(args, f.name, None) is not None
    }
    cfg = dataclasses.replace(cfg, **overrides)
    try:
        path = build(args.out_dir, cfg)
    except (RuntimeError, ValueError, FileNotFoundError) as exc:
        print(f"make_grid: {exc}", file=sys.stderr)
        return 1
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
