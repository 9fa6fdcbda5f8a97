"""The importer's base: the file, the problems found so far, attribute values through parameter scopes,
and positions (lane, world, road, relative lane) as SUMO lanes."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from lxml import etree

from .errors import Problems, ScenarioError, where
from .model import Entity
from .network import Lane, Network
from .opendrive import lane_at
from .parameters import Scope


def parse_file(path: Path) -> Any:
    try:
        return etree.parse(str(path), etree.XMLParser(remove_comments=True))
    except OSError as e:
        raise ScenarioError(f"{path}: cannot read it: {e}") from None
    except etree.XMLSyntaxError as e:
        raise ScenarioError(f"{path}:{e.lineno}: not well-formed XML: {e.msg}") from None


class Reader:
    def __init__(
        self,
        path: Path,
        network: Network,
        overrides: Mapping[str, Any],
        binds: Mapping[str, str],
        xodr: Path | None = None,
    ) -> None:
        self.path = path
        self.network = network
        self.overrides = overrides
        self.binds = dict(binds)
        self.problems = Problems(path)
        self.used: set[str] = set()
        self.entities: dict[str, Entity] = {}
        self.catalog_dirs: dict[str, Path] = {}  # "VehicleCatalog" -> its directory
        self.added: set[str] = set()  # entities an AddEntityAction puts on the road
        self.placed: dict[str, tuple[Lane, float]] = {}  # Init positions so far (for relative ones)
        self.xodr = xodr
        self.references: list[tuple[tuple[str, str], str]] = []  # StoryboardElementState targets
        self.globals: dict[str, Any] = {}  # the global parameters, as declared (or --param)

    # -- helpers ---------------------------------------------------------------------------
    def value(self, element: Any, name: str, scope: Scope, default: str | None = None) -> Any:
        text = element.get(name)
        if text is None:
            if default is None:
                raise ScenarioError(f"{where(self.path, element)}: attribute '{name}' is missing")
            text = default
        return scope.resolve(text, f"{where(self.path, element)} {name}")

    def number(self, element: Any, name: str, scope: Scope, default: str | None = None) -> float:
        value = self.value(element, name, scope, default)
        try:
            return float(value)
        except (TypeError, ValueError):
            raise ScenarioError(f"{where(self.path, element)}: {name}='{value}' is not a number") from None

    def text(self, element: Any, name: str, scope: Scope, default: str | None = None) -> str:
        return str(self.value(element, name, scope, default))

    def only(self, element: Any, allowed: set[str]) -> None:
        """Every child of `element` not in `allowed` is unsupported."""
        for child in element:
            if child.tag not in allowed:
                self.problems.add(child)

    def sumo_id(self, entity: str, element: Any) -> str:
        if entity not in self.entities:
            raise ScenarioError(f"{where(self.path, element)}: no entity '{entity}' is declared")
        return self.entities[entity].sumo_id

    def onward(self, lane: Lane) -> list[str]:
        """The edges from `lane`'s on, keeping straight on (as an entity without a route drives)."""
        route = self.network.follow(lane)
        return route if route[0] == lane.edge else [lane.edge, *route]

    def through(self, lanes: list[Lane]) -> tuple[str, list[str], list[str]]:
        """A route through `lanes`' edges in order that keeps straight on after the last (a SUMO trip
        ends at its route's end): (target edge, via edges, the lanes' edges)."""
        edges: list[str] = []
        for lane in lanes:
            if not edges or edges[-1] != lane.edge:
                edges.append(lane.edge)
        after = self.onward(lanes[-1])
        target = after[-1]
        via = [*edges, *after[1:-1]] if target != edges[-1] else edges[:-1]
        return target, via, edges

    def position(self, position: Any, scope: Scope, what: str) -> tuple[Lane | None, float]:
        if position is None or len(position) != 1:
            raise ScenarioError(f"{what}: a <Position> with one position in it is needed")
        p = position[0]
        here = where(self.path, p)
        if p.tag == "LanePosition":
            offset = self.number(p, "offset", scope, "0")
            if abs(offset) > 1e-9:
                self.problems.add(p, "a lateral offset")
                return None, 0.0
            return self.network.lane_position(
                self.text(p, "roadId", scope),
                int(self.number(p, "laneId", scope)),
                self.number(p, "s", scope),
                here,
            )
        if p.tag == "WorldPosition":
            return self.network.world_position(self.number(p, "x", scope), self.number(p, "y", scope), here)
        if p.tag == "RoadPosition":
            if self.xodr is None:
                raise ScenarioError(
                    f"{here}: a RoadPosition needs the scenario's OpenDRIVE file (RoadNetwork/LogicFile)"
                )
            road, s = self.text(p, "roadId", scope), self.number(p, "s", scope)
            lane_id = lane_at(self.xodr, road, s, self.number(p, "t", scope), here)
            return self.network.lane_position(road, lane_id, s, here)
        if p.tag == "RelativeLanePosition":
            entity = self.text(p, "entityRef", scope)
            reference = self.placed.get(entity)
            if reference is None:
                raise ScenarioError(f"{here}: entity '{entity}' has no lane position before this one")
            if abs(self.number(p, "offset", scope, "0")) > 1e-9 or p.get("dsLane") is not None:
                self.problems.add(p, "a lateral offset or dsLane")
                return None, 0.0
            lane, pos = reference
            lanes = self.network.edges[lane.edge]
            # dLane counts to the left in the reference entity's direction: SUMO's index goes up.
            index = lane.index + int(self.number(p, "dLane", scope))
            if not 0 <= index < len(lanes):
                raise ScenarioError(f"{here}: dLane leaves edge '{lane.edge}' ({len(lanes)} lanes)")
            target = lanes[index]
            s = pos + self.number(p, "ds", scope, "0")
            if not 0 <= s <= target.length:
                raise ScenarioError(f"{here}: ds puts it off edge '{lane.edge}' (length {target.length:g} m)")
            return target, s
        self.problems.add(p)
        return None, 0.0

    def catalog_entry(self, reference: Any, scope: Scope, kind: str) -> tuple[Any, Scope]:
        """The `kind` (Vehicle, Maneuver) a CatalogReference names, and the scope of its parameters: the
        entry's declarations with the reference's assignments."""
        catalog = self.text(reference, "catalogName", scope)
        entry = self.text(reference, "entryName", scope)
        directory = self.catalog_dirs.get(f"{kind}Catalog")
        if directory is None:
            raise ScenarioError(f"{where(self.path, reference)}: no {kind}Catalog directory in CatalogLocations")
        assignments: dict[str, Any] = {}
        holder = reference.find("ParameterAssignments")
        if holder is not None:
            for a in holder.iterfind("ParameterAssignment"):
                assignments[self.text(a, "parameterRef", scope)] = self.value(a, "value", scope)
        for file in sorted(directory.glob("*.xosc")):
            doc = parse_file(file)
            for cat in doc.getroot().iterfind("Catalog"):
                if cat.get("name") != catalog:
                    continue
                for element in cat.iterfind(kind):
                    if element.get("name") == entry:
                        declared = element.find("ParameterDeclarations")
                        local = Scope(parent=scope).declare(declared, file, assignments, set())
                        # The entry's own declarations are applied here; declare() again does nothing new.
                        if declared is not None:
                            element.remove(declared)
                        return element, local
        raise ScenarioError(
            f"{where(self.path, reference)}: catalog '{catalog}' has no {kind.lower()} '{entry}' in {directory}"
        )
