"""Small, deterministic SUMO grid scenarios for sbsim (tests, benchmarks, the bundled stories).

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
runs that produce identical outputs.  The SUMO binaries are those of the
``eclipse-sumo`` package of the running interpreter (:mod:`sbsim.sumo`).

The parameters are the fields of :class:`GridConfig`, spelled once: each field's
``help`` is its documentation, and the same fields make the command line's options
(:meth:`GridConfig.add_arguments`).  Use::

    from sbsim.scenarios.grid import make_grid, make_preset
    cfg = make_grid(tmp_path, grid=4, end=200.0, seed=1)
    bench_cfg = make_preset(tmp_path / "b", "bench5k")

or the command line ``python tools/make_grid.py OUT_DIR --grid 4 --end 200 --seed 1``
(``--preset bench5k``, ``--list-presets``).
"""

from __future__ import annotations

import argparse
import dataclasses
import math
import random
import re
import subprocess
import sys
import tempfile
import types
import typing
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal, get_args

from sbsim.sumo import sumo_binary, sumo_environment, sumo_home

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


def _parameter(default: Any, help: str, flag: str | None = None) -> Any:
    """A :class:`GridConfig` field: its default and its one line of documentation (also the option's
    help). ``flag`` names a bool's option, which sets the field to the opposite of its default."""
    return field(default=default, metadata={"help": help, "flag": flag})


@dataclass(frozen=True)
class GridConfig:
    """All parameters of a generated scenario (each field's ``help`` says what it is)."""

    name: str = _parameter("grid", "base name of the .sumocfg")
    grid: int = _parameter(5, "junctions per side (grid x grid junctions)")
    spacing: float = _parameter(200.0, "distance between neighbouring junctions [m]")
    lanes: int = _parameter(1, "lanes per direction")
    speed: float = _parameter(13.89, "speed limit [m/s]")
    junction: JunctionType = _parameter(
        "traffic_light", "netgenerate junction type; with traffic_light the four corners stay priority junctions"
    )
    tls_type: TlsType = _parameter(
        "static", "netgenerate tls.default-type; actuated gives steadier queues than fixed-time static"
    )
    begin: float = _parameter(0.0, "begin time written into the .sumocfg [s]")
    end: float = _parameter(300.0, "end time written into the .sumocfg [s]")
    step_length: float = _parameter(1.0, "simulation step length [s]")
    seed: int = _parameter(42, "seed of netgenerate, randomTrips, the loop generator and SUMO")
    traffic: TrafficMode = _parameter(
        "trips", "trips: random trips, one per period; loops: vehicles on endless loops, inserted during ramp"
    )
    period: float = _parameter(1.0, "trips: insertion period [s]")
    min_distance: float | None = _parameter(None, "trips: minimum straight-line trip distance [m]")
    vehicles: int = _parameter(1000, "loops: number of vehicles")
    ramp: float = _parameter(100.0, "loops: the time over which all vehicles are inserted [s]")
    truck_share: float = _parameter(0.2, "probability that a vehicle gets vType truck")
    time_to_teleport: float = _parameter(120.0, "SUMO's time-to-teleport [s]")
    ignore_junction_blocker: float = _parameter(30.0, "SUMO's ignore-junction-blocker [s]")
    quiet: bool = _parameter(
        True,
        "write no-warnings and xml-validation=never into the .sumocfg (validation needs SUMO_HOME and warns "
        "without it)",
        flag="--warnings",
    )
    additional_files: str = _parameter(
        "", "written into the .sumocfg's additional-files as is (comma-separated, relative to it); empty: none"
    )

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

    @classmethod
    def add_arguments(cls, parser: argparse.ArgumentParser) -> None:
        """One option per field (``--step-length`` for ``step_length``), each defaulting to None: only
        the options given override a preset (:meth:`overrides`)."""
        hints = typing.get_type_hints(cls)
        for f in dataclasses.fields(cls):
            kind, help_text = hints[f.name], f"{f.metadata['help']} (default: {f.default})"
            if kind is bool:
                help_text = f"set {f.name} to {not f.default}; {f.name}: {help_text}"
                parser.add_argument(
                    f.metadata["flag"], dest=f.name, action="store_const", const=not f.default, help=help_text
                )
                continue
            if isinstance(kind, types.UnionType):  # an optional value: its type is the one not None
                [kind] = [k for k in get_args(kind) if k is not type(None)]
            option = "--" + f.name.replace("_", "-")
            if typing.get_origin(kind) is Literal:
                parser.add_argument(option, choices=get_args(kind), help=help_text)
            else:
                parser.add_argument(option, type=kind, help=help_text)

    @classmethod
    def overrides(cls, arguments: argparse.Namespace) -> dict[str, Any]:
        """The fields the command line set (the options :meth:`add_arguments` made that were given)."""
        return {
            f.name: getattr(arguments, f.name)
            for f in dataclasses.fields(cls)
            if getattr(arguments, f.name, None) is not None
        }


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
# SUMO's tools
# --------------------------------------------------------------------------- #


def _run(cmd: Sequence[str | Path], cwd: Path) -> None:
    proc = subprocess.run(
        [str(c) for c in cmd],
        cwd=cwd,
        env=sumo_environment(),
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
    # An empty field added later is left out, so older scenarios regenerate identical files; for the
    # same reason the comment still names the generator by its command line, tools/make_grid.py.
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


def make_grid(out_dir: Path | str, **parameters: Any) -> Path:
    """Generate a deterministic grid scenario in ``out_dir`` (created if missing, files overwritten):
    ``net.net.xml``, ``routes.rou.xml`` and ``<name>.sumocfg``, whose path is returned.

    ``parameters`` are :class:`GridConfig` fields (``grid=4, end=200.0, seed=1``); the others keep
    their defaults."""
    return build(out_dir, GridConfig(**parameters))


def make_preset(out_dir: Path | str, preset: str, **overrides: object) -> Path:
    """Generate a named preset (see :data:`PRESETS`), optionally overridden."""
    try:
        cfg = PRESETS[preset]
    except KeyError:
        raise ValueError(f"unknown preset {preset!r}; choose from {', '.join(PRESETS)}") from None
    cfg = dataclasses.replace(cfg, **overrides)  # type: ignore[arg-type]
    return build(out_dir, cfg)
