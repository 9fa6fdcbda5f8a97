"""Reads an OpenSCENARIO 1.x file into what sbsim runs: entities, their initial state, and the
storyboard as a tree of elements whose triggers and actions are recipes for storyboard conditions
and effects (built inside sbsim by :mod:`.stories`). Whatever is not supported is collected, and
one error lists every such element with its line."""

from __future__ import annotations

import importlib.util
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from lxml import etree

from .errors import Problems, ScenarioError, where
from .network import Lane, Network
from .opendrive import lane_at
from .parameters import Scope

# vehicleCategory -> SUMO vehicle class.
VEHICLE_CLASSES = {
    "car": "passenger",
    "van": "delivery",
    "truck": "truck",
    "trailer": "trailer",
    "semitrailer": "trailer",
    "bus": "bus",
    "motorbike": "motorcycle",
    "bicycle": "bicycle",
}

SHAPES = ("step", "linear", "cubic", "sinusoidal")
DIMENSIONS = ("time", "distance", "rate")
RULES = ("greaterThan", "lessThan", "equalTo", "greaterOrEqual", "lessOrEqual", "notEqualTo")
EDGES = ("none", "rising", "falling", "risingOrFalling")
STATES = (
    "standbyState",
    "runningState",
    "completeState",
    "startTransition",
    "endTransition",
    "stopTransition",
    "skipTransition",
)
ELEMENT_KINDS = {
    "story": "story",
    "act": "act",
    "maneuverGroup": "maneuver_group",
    "maneuver": "maneuver",
    "event": "event",
}


@dataclass
class Build:
    """What recipes build with inside sbsim: the storyboard module, the machine and its element
    indices, the run's parameter store."""

    sb: Any
    machine: Any
    index: dict[tuple[str, str], int]  # (kind, name) -> machine element
    params: Any = None


Recipe = Callable[[Build], Any]


@dataclass
class Entity:
    name: str
    sumo_id: str
    vclass: str
    length: float
    width: float
    height: float
    max_speed: float
    max_accel: float
    max_decel: float
    bound: bool

    @property
    def vtype(self) -> str:
        return f"xosc_{self.name}"


@dataclass
class Start:
    """An entity's Init: where it is put (lane, position), its speed, its route."""

    entity: str
    lane: Lane | None = None
    pos: float = 0.0
    speed: float | None = None
    route: list[str] | None = None


@dataclass
class TriggerCondition:
    name: str
    edge: str
    delay: float
    recipe: Recipe


Trigger = list[list[TriggerCondition]]


@dataclass
class Action:
    name: str
    world: bool  # a world effect (AddEntity): the event's world story holds it
    describe: str
    recipe: Recipe


@dataclass
class Element:
    kind: str  # storyboard, story, act, maneuver_group, maneuver, event
    name: str
    path: str  # "Story/Act/Event" for the event log
    children: list[Element] = field(default_factory=list)
    start: Trigger = field(default_factory=list)
    stop: Trigger = field(default_factory=list)
    max_executions: int = 1
    priority: str = "parallel"
    actors: list[str] = field(default_factory=list)
    actions: list[Action] = field(default_factory=list)


@dataclass
class Scenario:
    path: Path
    network: Network
    entities: dict[str, Entity]
    starts: list[Start]
    storyboard: Element
    parameters: dict[str, Any]  # the global ones


def schema_for(root: Any) -> Path | None:
    """The ASAM OpenSCENARIO XSD of the file's revision, as the scenariogeneration package ships it."""
    spec = importlib.util.find_spec("scenariogeneration")
    if spec is None or spec.origin is None:
        return None
    schemas = Path(spec.origin).parent.parent / "schemas"
    header = root.find("FileHeader")
    minor = header.get("revMinor", "2") if header is not None else "2"
    name = {"0": "OpenSCENARIO_1_0.xsd", "1": "OpenSCENARIO_1_1.xsd", "2": "OpenSCENARIO_1_2.xsd"}.get(
        minor, "OpenSCENARIO_1_3_1.xsd"
    )
    return schemas / name if (schemas / name).exists() else None


def parse_file(path: Path) -> Any:
    try:
        return etree.parse(str(path), etree.XMLParser(remove_comments=True))
    except OSError as e:
        raise ScenarioError(f"{path}: cannot read it: {e}") from None
    except etree.XMLSyntaxError as e:
        raise ScenarioError(f"{path}:{e.lineno}: not well-formed XML: {e.msg}") from None


def validate(path: Path, tree: Any) -> bool:
    """Checks the file against the ASAM schema when one is available; False when none is."""
    xsd = schema_for(tree.getroot())
    if xsd is None:
        return False
    schema = etree.XMLSchema(etree.parse(str(xsd)))
    if not schema.validate(tree):
        error = schema.error_log[0]
        raise ScenarioError(f"{path}:{error.line}: fails the ASAM schema ({xsd.name}): {error.message}")
    return True


class Importer:
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
        self.catalog_dirs: dict[str, Path] = {}
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

    # -- the document ----------------------------------------------------------------------
    def read(self, tree: Any) -> Scenario:
        root = tree.getroot()
        if root.tag != "OpenSCENARIO":
            raise ScenarioError(f"{where(self.path, root)}: not an OpenSCENARIO file")
        self.only(
            root, {"FileHeader", "ParameterDeclarations", "CatalogLocations", "RoadNetwork", "Entities", "Storyboard"}
        )
        scope = Scope().declare(root.find("ParameterDeclarations"), self.path, self.overrides, self.used)
        self.globals = dict(scope.values)
        catalogs = root.find("CatalogLocations")
        if catalogs is not None:
            for location in catalogs:
                directory = location.find("Directory")
                if location.tag != "VehicleCatalog" or directory is None:
                    self.problems.add(location)
                    continue
                self.catalog_dirs[location.tag] = (self.path.parent / self.text(directory, "path", scope)).resolve()
        road = root.find("RoadNetwork")
        if road is not None:
            self.only(road, {"LogicFile", "SceneGraphFile", "TrafficSignals"})
            signals = road.find("TrafficSignals")
            if signals is not None and len(signals):
                self.problems.add(signals)
        entities = root.find("Entities")
        if entities is not None:
            for obj in entities:
                if obj.tag != "ScenarioObject":
                    self.problems.add(obj)
                    continue
                self.read_object(obj, scope)
        for name in self.binds:
            if name not in self.entities:
                raise ScenarioError(f"--bind {name}={self.binds[name]}: {self.path} has no entity '{name}'")
        board = root.find("Storyboard")
        if board is None:
            raise ScenarioError(f"{where(self.path, root)}: no <Storyboard>")
        starts = self.read_init(board.find("Init"), scope)
        storyboard = Element("storyboard", "Storyboard", "Storyboard")
        for child in board:
            if child.tag == "Story":
                storyboard.children.append(self.read_story(child, scope))
            elif child.tag == "StopTrigger":
                storyboard.stop = self.read_trigger(child, scope)
            elif child.tag != "Init":
                self.problems.add(child)
        self.problems.raise_if_any()
        named = {(e.kind, e.name) for e in _elements(storyboard)}
        for key, missing in self.references:
            if key not in named:
                raise ScenarioError(missing)
        positioned = {s.entity for s in starts if s.lane is not None}
        for e in self.entities.values():
            if not e.bound and e.name not in positioned and e.name not in self.added:
                raise ScenarioError(
                    f"{self.path}: entity '{e.name}' has no position in Init (a TeleportAction) and is not "
                    f"bound to a SUMO vehicle (--bind {e.name}=VEHICLE)"
                )
        return Scenario(self.path, self.network, self.entities, starts, storyboard, dict(self.globals))

    def read_object(self, obj: Any, scope: Scope) -> None:
        name = self.text(obj, "name", scope)
        self.only(obj, {"Vehicle", "CatalogReference", "ObjectController"})
        controller = obj.find("ObjectController")
        if controller is not None and len(controller):
            self.problems.add(controller, "controllers (SUMO's driver model drives)")
        vehicle = obj.find("Vehicle")
        local = scope
        reference = obj.find("CatalogReference")
        if reference is not None:
            vehicle, local = self.from_catalog(reference, scope)
        if vehicle is None:
            if reference is None and not any(c.tag not in ("Vehicle", "ObjectController") for c in obj):
                self.problems.add(obj, "only Vehicle entities")
            return
        local = local.declare(vehicle.find("ParameterDeclarations"), self.path)
        self.only(vehicle, {"ParameterDeclarations", "Performance", "BoundingBox", "Axles", "Properties"})
        category = self.text(vehicle, "vehicleCategory", local)
        if category not in VEHICLE_CLASSES:
            self.problems.add(vehicle, f"vehicleCategory '{category}'")
            return
        dims = vehicle.find("BoundingBox/Dimensions")
        perf = vehicle.find("Performance")
        length = self.number(dims, "length", local) if dims is not None else 4.5
        width = self.number(dims, "width", local) if dims is not None else 1.8
        height = self.number(dims, "height", local) if dims is not None else 1.5
        sumo_id = self.binds.get(name, name)
        self.entities[name] = Entity(
            name,
            sumo_id,
            VEHICLE_CLASSES[category],
            length,
            width,
            height,
            self.number(perf, "maxSpeed", local) if perf is not None else 70.0,
            self.number(perf, "maxAcceleration", local) if perf is not None else 2.6,
            self.number(perf, "maxDeceleration", local) if perf is not None else 4.5,
            name in self.binds,
        )

    def from_catalog(self, reference: Any, scope: Scope) -> tuple[Any, Scope]:
        catalog = self.text(reference, "catalogName", scope)
        entry = self.text(reference, "entryName", scope)
        directory = self.catalog_dirs.get("VehicleCatalog")
        if directory is None:
            raise ScenarioError(f"{where(self.path, reference)}: no VehicleCatalog directory in CatalogLocations")
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
                for vehicle in cat.iterfind("Vehicle"):
                    if vehicle.get("name") == entry:
                        declared = vehicle.find("ParameterDeclarations")
                        local = Scope(parent=scope).declare(declared, file, assignments, set())
                        # The entry's own declarations are applied here; declare() again does nothing new.
                        if declared is not None:
                            vehicle.remove(declared)
                        return vehicle, local
        raise ScenarioError(
            f"{where(self.path, reference)}: catalog '{catalog}' has no vehicle '{entry}' in {directory}"
        )

    # -- Init --------------------------------------------------------------------------------
    def read_init(self, init: Any, scope: Scope) -> list[Start]:
        starts: list[Start] = []
        if init is None:
            return starts
        actions = init.find("Actions")
        self.only(init, {"Actions"})
        if actions is None:
            return starts
        for private in actions:
            if private.tag != "Private":
                self.problems.add(private)
                continue
            entity = self.text(private, "entityRef", scope)
            self.sumo_id(entity, private)
            start = Start(entity)
            for pa in private:
                for action in pa:
                    self.read_init_action(action, start, scope)
            starts.append(start)
        return starts

    def read_init_action(self, action: Any, start: Start, scope: Scope) -> None:
        what = where(self.path, action)
        if action.tag == "TeleportAction":
            lane, pos = self.position(action.find("Position"), scope, what)
            if lane is not None:
                start.lane, start.pos = lane, pos
                self.placed[start.entity] = (lane, pos)
        elif action.tag == "LongitudinalAction" and action.find("SpeedAction") is not None:
            speed = action.find("SpeedAction")
            target = speed.find("SpeedActionTarget/AbsoluteTargetSpeed")
            if target is None:
                self.problems.add(speed, "an Init speed must be an AbsoluteTargetSpeed")
                return
            start.speed = self.number(target, "value", scope)
        elif action.tag == "RoutingAction" and action.find("AssignRouteAction") is not None:
            route = action.find("AssignRouteAction/Route")
            if route is None:
                self.problems.add(action, "a CatalogReference route")
                return
            edges: list[str] = []
            for waypoint in route.iterfind("Waypoint"):
                lane, _ = self.position(waypoint.find("Position"), scope, where(self.path, waypoint))
                if lane is not None and (not edges or edges[-1] != lane.edge):
                    edges.append(lane.edge)
            start.route = edges
        else:
            self.problems.add(action)

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

    # -- Storyboard ----------------------------------------------------------------------------
    def read_story(self, story: Any, scope: Scope) -> Element:
        name = self.text(story, "name", scope)
        local = scope.declare(story.find("ParameterDeclarations"), self.path)
        element = Element("story", name, name)
        for act in story:
            if act.tag == "Act":
                element.children.append(self.read_act(act, local, name))
            elif act.tag != "ParameterDeclarations":
                self.problems.add(act)
        return element

    def read_act(self, act: Any, scope: Scope, story: str) -> Element:
        name = self.text(act, "name", scope)
        element = Element("act", name, f"{story}/{name}")
        for child in act:
            if child.tag == "ManeuverGroup":
                element.children.append(self.read_group(child, scope, element.path))
            elif child.tag == "StartTrigger":
                element.start = self.read_trigger(child, scope)
            elif child.tag == "StopTrigger":
                element.stop = self.read_trigger(child, scope)
            else:
                self.problems.add(child)
        return element

    def read_group(self, group: Any, scope: Scope, act_path: str) -> Element:
        name = self.text(group, "name", scope)
        element = Element("maneuver_group", name, f"{act_path}/{name}")
        if int(self.number(group, "maximumExecutionCount", scope, "1")) != 1:
            self.problems.add(group, "a ManeuverGroup maximumExecutionCount other than 1")
        actors = group.find("Actors")
        if actors is not None:
            if self.text(actors, "selectTriggeringEntities", scope, "false") == "true":
                self.problems.add(actors, "selectTriggeringEntities=true")
            for ref in actors:
                if ref.tag != "EntityRef":
                    self.problems.add(ref)
                    continue
                element.actors.append(self.sumo_id(self.text(ref, "entityRef", scope), ref))
        for child in group:
            if child.tag == "Maneuver":
                element.children.append(self.read_maneuver(child, scope, act_path, element.actors))
            elif child.tag not in ("Actors",):
                self.problems.add(child, "catalog maneuvers" if child.tag == "CatalogReference" else "")
        return element

    def read_maneuver(self, maneuver: Any, scope: Scope, act_path: str, actors: list[str]) -> Element:
        name = self.text(maneuver, "name", scope)
        local = scope.declare(maneuver.find("ParameterDeclarations"), self.path)
        element = Element("maneuver", name, f"{act_path}/{name}")
        for child in maneuver:
            if child.tag == "Event":
                element.children.append(self.read_event(child, local, act_path, actors))
            elif child.tag != "ParameterDeclarations":
                self.problems.add(child)
        return element

    def read_event(self, event: Any, scope: Scope, act_path: str, actors: list[str]) -> Element:
        name = self.text(event, "name", scope)
        priority = self.text(event, "priority", scope, "parallel")
        priority = {"override": "overwrite"}.get(priority, priority)  # 1.2's new name for overwrite
        if priority not in ("parallel", "overwrite", "skip"):
            self.problems.add(event, f"priority '{priority}'")
            priority = "parallel"
        element = Element(
            "event",
            name,
            f"{act_path}/{name}",
            max_executions=int(self.number(event, "maximumExecutionCount", scope, "1")),
            priority=priority,
            actors=list(actors),
        )
        for child in event:
            if child.tag == "Action":
                action = self.read_action(child, scope, actors)
                if action is not None:
                    element.actions.append(action)
            elif child.tag == "StartTrigger":
                element.start = self.read_trigger(child, scope)
            else:
                self.problems.add(child)
        return element

    # -- actions -----------------------------------------------------------------------------
    def read_action(self, action: Any, scope: Scope, actors: list[str]) -> Action | None:
        name = self.text(action, "name", scope)
        if len(action) != 1:
            self.problems.add(action, "an Action holds one action")
            return None
        kind = action[0]
        if kind.tag == "PrivateAction" and len(kind) == 1:
            inner = kind[0]
            speed = inner.find("SpeedAction") if inner.tag == "LongitudinalAction" else None
            if speed is not None:
                return self.read_speed(speed, scope, name)
            if inner.tag == "LateralAction" and len(inner) == 1 and inner[0].tag == "LaneChangeAction":
                return self.read_lane_change(inner[0], scope, name, actors)
            if inner.tag == "LateralAction" and len(inner) == 1 and inner[0].tag == "LaneOffsetAction":
                return self.read_lane_offset(inner[0], scope, name)
            self.problems.add(inner)
            return None
        if kind.tag == "UserDefinedAction" and len(kind) == 1 and kind[0].tag == "CustomCommandAction":
            command = kind[0]
            if self.text(command, "type", scope) != "SignalEffect":
                self.problems.add(command, "CustomCommandAction type other than 'SignalEffect'")
                return None
            cause = str(scope.resolve((command.text or "").strip(), where(self.path, command)))
            if not cause:
                raise ScenarioError(f"{where(self.path, command)}: a SignalEffect needs its cause as the text")
            return Action(name, False, f"SignalEffect('{cause}')", lambda b: b.sb.SignalEffect(cause))
        if kind.tag == "GlobalAction" and len(kind) == 1 and kind[0].tag == "ParameterAction":
            return self.read_parameter_action(kind[0], scope, name)
        if kind.tag == "GlobalAction" and kind.find("EntityAction/DeleteEntityAction") is not None:
            entity_action = kind.find("EntityAction")
            sumo_id = self.sumo_id(self.text(entity_action, "entityRef", scope), entity_action)
            return Action(name, True, f"RemoveVehicleEffect({sumo_id})", lambda b: b.sb.RemoveVehicleEffect(sumo_id))
        if kind.tag == "GlobalAction" and kind.find("EntityAction/AddEntityAction") is not None:
            entity_action = kind.find("EntityAction")
            entity = self.text(entity_action, "entityRef", scope)
            sumo_id = self.sumo_id(entity, entity_action)
            self.added.add(entity)
            add = entity_action.find("AddEntityAction")
            lane, pos = self.position(add.find("Position"), scope, where(self.path, add))
            if lane is None:
                return None
            route = self.network.follow(lane)
            vtype = self.entities[entity].vtype
            index = lane.index
            return Action(
                name,
                True,
                f"SpawnEffect({sumo_id})",
                lambda b: b.sb.SpawnEffect(sumo_id, route=route, type=vtype, lane=index, position=pos),
            )
        self.problems.add(kind)
        return None

    def read_parameter_action(self, action: Any, scope: Scope, name: str) -> Action | None:
        ref = self.text(action, "parameterRef", scope)
        here = where(self.path, action)
        if ref not in self.globals:
            raise ScenarioError(f"{here}: '{ref}' is no global parameter (only those may change in a run)")
        op: str
        operand: Any
        if len(action) == 1 and action[0].tag == "SetAction":
            op, operand = "set", _as_stored(self.globals[ref], self.value(action[0], "value", scope), here)
        elif len(action) == 1 and action[0].tag == "ModifyAction" and len(action[0]) == 1 and len(action[0][0]) == 1:
            rule = action[0][0][0]
            if rule.tag not in ("AddValue", "MultiplyByValue") or isinstance(self.globals[ref], str):
                self.problems.add(rule, "AddValue or MultiplyByValue of a number")
                return None
            op, operand = ("add" if rule.tag == "AddValue" else "multiply"), self.number(rule, "value", scope)
        else:
            self.problems.add(action)
            return None
        return Action(
            name, True, f"ParameterEffect({ref} {op})", lambda b: b.sb.ParameterEffect(b.params, ref, op, operand)
        )

    def transition(self, dynamics: Any, scope: Scope) -> tuple[str, str, float] | None:
        """TransitionDynamics as (shape, dimension, value); None (a problem) for what sbsim lacks."""
        shape = self.text(dynamics, "dynamicsShape", scope)
        dimension = self.text(dynamics, "dynamicsDimension", scope, "time")
        if shape not in SHAPES or dimension not in DIMENSIONS:
            self.problems.add(dynamics, f"dynamicsShape '{shape}' with dynamicsDimension '{dimension}'")
            return None
        if dynamics.get("followingMode") not in (None, "position"):
            self.problems.add(dynamics, "followingMode 'follow' (the shape is followed exactly)")
            return None
        return shape, dimension, self.number(dynamics, "value", scope, "0")

    def read_speed(self, speed: Any, scope: Scope, name: str) -> Action | None:
        dynamics = speed.find("SpeedActionDynamics")
        target = speed.find("SpeedActionTarget")
        if dynamics is None or target is None or len(target) != 1:
            self.problems.add(speed, "a SpeedAction needs SpeedActionDynamics and a SpeedActionTarget")
            return None
        law = self.transition(dynamics, scope)
        if law is None:
            return None
        shape, dimension, by = law
        inner = target[0]
        if inner.tag == "AbsoluteTargetSpeed":
            value = self.number(inner, "value", scope)
            if shape == "step":
                # At once, within SUMO's safety checks (its acceleration bounds), kept after.
                return Action(name, False, f"SetSpeedEffect({value:g} m/s)", lambda b: b.sb.SetSpeedEffect(value))

            def absolute(b: Build) -> Any:
                return b.sb.SpeedChangeEffect(value, shape, dimension, by, keep=True)

            return Action(name, False, f"SpeedChangeEffect({value:g} m/s, {shape} {dimension} {by:g})", absolute)
        if inner.tag == "RelativeTargetSpeed":
            other = self.sumo_id(self.text(inner, "entityRef", scope), inner)
            value = self.number(inner, "value", scope)
            kind = self.text(inner, "speedTargetValueType", scope)
            continuous = self.text(inner, "continuous", scope, "false") == "true"
            if kind not in ("delta", "factor"):
                raise ScenarioError(
                    f"{where(self.path, inner)}: speedTargetValueType '{kind}' is none of delta, factor"
                )

            def relative(b: Build) -> Any:
                return b.sb.SpeedChangeEffect(
                    value, shape, dimension, by, relative_to=other, value_type=kind, continuous=continuous, keep=True
                )

            return Action(name, False, f"SpeedChangeEffect({other}'s speed {kind} {value:g})", relative)
        self.problems.add(inner)
        return None

    def read_lane_change(self, change: Any, scope: Scope, name: str, actors: list[str]) -> Action | None:
        dynamics = change.find("LaneChangeActionDynamics")
        target = change.find("LaneChangeTarget")
        if dynamics is None or target is None or len(target) != 1:
            self.problems.add(change, "a LaneChangeAction needs LaneChangeActionDynamics and a LaneChangeTarget")
            return None
        law = self.transition(dynamics, scope)
        if law is None:
            return None
        shape, dimension, by = law
        if dimension == "rate":
            self.problems.add(dynamics, "a lane change by rate (time and distance are)")
            return None
        offset = self.number(change, "targetLaneOffset", scope, "0")
        inner = target[0]
        if inner.tag == "RelativeTargetLane":
            other = self.sumo_id(self.text(inner, "entityRef", scope), inner)
            lanes = int(self.number(inner, "value", scope))  # positive: to the left, as SUMO's index goes
            own = actors == [other]

            def relative(b: Build) -> Any:
                if own:
                    return b.sb.LaneChangeEffect(lanes, shape, dimension, by, relative=True, offset=offset)
                return b.sb.LaneChangeEffect(lanes, shape, dimension, by, relative_to=other, offset=offset)

            return Action(name, False, f"LaneChangeEffect({other}'s lane {lanes:+d})", relative)
        if inner.tag == "AbsoluteTargetLane":
            index = self.network.lane_index(int(self.number(inner, "value", scope)), where(self.path, inner))

            def absolute(b: Build) -> Any:
                return b.sb.LaneChangeEffect(index, shape, dimension, by, offset=offset)

            return Action(name, False, f"LaneChangeEffect(lane {index})", absolute)
        self.problems.add(inner)
        return None

    def read_lane_offset(self, action: Any, scope: Scope, name: str) -> Action | None:
        dynamics = action.find("LaneOffsetActionDynamics")
        target = action.find("LaneOffsetTarget/AbsoluteTargetLaneOffset")
        if dynamics is None or target is None:
            self.problems.add(action, "a LaneOffsetAction needs its dynamics and an AbsoluteTargetLaneOffset")
            return None
        if self.text(action, "continuous", scope, "false") == "true":
            self.problems.add(action, "continuous=true (the offset is reached once, then SUMO aligns the vehicle)")
            return None
        shape = self.text(dynamics, "dynamicsShape", scope)
        if shape not in SHAPES:
            self.problems.add(dynamics, f"dynamicsShape '{shape}'")
            return None
        acc = float(self.number(dynamics, "maxLateralAcc", scope)) if dynamics.get("maxLateralAcc") else None
        if acc is None and shape != "step":
            self.problems.add(dynamics, f"a {shape} lane offset without maxLateralAcc (its time comes from it)")
            return None
        offset = self.number(target, "value", scope)
        return Action(
            name,
            False,
            f"LaneOffsetEffect({offset:+g} m)",
            lambda b: b.sb.LaneOffsetEffect(offset, shape, max_lateral_acc=acc),
        )

    # -- triggers and conditions ---------------------------------------------------------------
    def read_trigger(self, trigger: Any, scope: Scope) -> Trigger:
        groups: Trigger = []
        for group in trigger:
            if group.tag != "ConditionGroup":
                self.problems.add(group)
                continue
            conditions = []
            for condition in group:
                c = self.read_condition(condition, scope)
                if c is not None:
                    conditions.append(c)
            if conditions:
                groups.append(conditions)
        return groups

    def read_condition(self, condition: Any, scope: Scope) -> TriggerCondition | None:
        if condition.tag != "Condition" or len(condition) != 1:
            self.problems.add(condition)
            return None
        name = self.text(condition, "name", scope)
        edge = self.text(condition, "conditionEdge", scope)
        if edge not in EDGES:
            raise ScenarioError(f"{where(self.path, condition)}: conditionEdge '{edge}' is none of {', '.join(EDGES)}")
        delay = self.number(condition, "delay", scope, "0")
        body = condition[0]
        recipe: Recipe | None = None
        if body.tag == "ByValueCondition" and len(body) == 1:
            recipe = self.by_value(body[0], scope)
        elif body.tag == "ByEntityCondition":
            recipe = self.by_entity(body, scope)
        else:
            self.problems.add(body)
        return None if recipe is None else TriggerCondition(name, edge, delay, recipe)

    def rule(self, element: Any, scope: Scope) -> str:
        rule = self.text(element, "rule", scope)
        if rule not in RULES:
            raise ScenarioError(f"{where(self.path, element)}: rule '{rule}' is none of {', '.join(RULES)}")
        return rule

    def by_value(self, c: Any, scope: Scope) -> Recipe | None:
        if c.tag == "SimulationTimeCondition":
            value, rule = self.number(c, "value", scope), self.rule(c, scope)
            return lambda b: _compare_time(b.sb, value, rule)
        if c.tag == "ParameterCondition":
            ref = self.text(c, "parameterRef", scope)
            rule = self.rule(c, scope)
            values = scope.all()
            if ref not in values:
                raise ScenarioError(f"{where(self.path, c)}: no parameter '{ref}' is declared")
            if ref in self.globals:
                # A global parameter may change during the run (ParameterSetAction): asked each step.
                value = _as_stored(self.globals[ref], self.value(c, "value", scope), where(self.path, c))
                return lambda b: b.sb.ParameterCondition(b.params, ref, rule, value)
            # A parameter of a Story or Maneuver never changes: decided now.
            holds = _compare_values(values[ref], self.value(c, "value", scope), rule)
            return lambda b: b.sb.TimeCondition(0) if holds else b.sb.NotCondition(b.sb.TimeCondition(0))
        if c.tag == "StoryboardElementStateCondition":
            kind = self.text(c, "storyboardElementType", scope)
            ref = self.text(c, "storyboardElementRef", scope)
            state = self.text(c, "state", scope)
            if kind not in ELEMENT_KINDS or state not in STATES:
                self.problems.add(c, f"element type '{kind}' or state '{state}'")
                return None
            key = (ELEMENT_KINDS[kind], ref)
            self.references.append((key, f"{where(self.path, c)}: no {kind} named '{ref}' in the storyboard"))

            def element_state(b: Build) -> Any:
                return b.sb.ElementStateCondition(b.machine, b.index[key], state)

            return element_state
        self.problems.add(c)
        return None

    def by_entity(self, body: Any, scope: Scope) -> Recipe | None:
        triggering = body.find("TriggeringEntities")
        inner = body.find("EntityCondition")
        if triggering is None or inner is None or len(inner) != 1:
            self.problems.add(body)
            return None
        rule_all = self.text(triggering, "triggeringEntitiesRule", scope) == "all"
        ids = [self.sumo_id(self.text(r, "entityRef", scope), r) for r in triggering.iterfind("EntityRef")]
        make = self.entity_condition(inner[0], scope)
        if make is None:
            return None

        def build(b: Build) -> Any:
            parts = [b.sb.EntityCondition(i, make(b)) for i in ids]
            if len(parts) == 1:
                return parts[0]
            return b.sb.AllCondition(*parts) if rule_all else b.sb.AnyCondition(*parts)

        return build

    def entity_condition(self, c: Any, scope: Scope) -> Recipe | None:
        """A recipe for the condition about one (triggering) vehicle, the ego of the built tree."""
        tag = c.tag
        if tag == "SpeedCondition":
            value, rule = self.number(c, "value", scope), self.rule(c, scope)
            return lambda b: _compare(b.sb, b.sb.SpeedConditionGreater, b.sb.SpeedConditionLess, value, rule)
        if tag == "AccelerationCondition":
            if c.get("direction") not in (None, "longitudinal"):
                self.problems.add(c, "a direction other than longitudinal")
                return None
            value, rule = self.number(c, "value", scope), self.rule(c, scope)
            return lambda b: _compare(
                b.sb, b.sb.AccelerationConditionGreater, b.sb.AccelerationConditionLess, value, rule
            )
        if tag == "StandStillCondition":
            duration = self.number(c, "duration", scope)
            return lambda b: b.sb.StandstillCondition(duration)
        if tag == "ReachPositionCondition":
            tolerance = self.number(c, "tolerance", scope)
            lane, pos = self.position(c.find("Position"), scope, where(self.path, c))
            if lane is None:
                return None
            point = self.network.xy(lane, pos)
            return lambda b: b.sb.DistanceCondition(point, tolerance)
        if tag == "DistanceCondition":
            return self.distance(c, scope)
        if tag == "RelativeDistanceCondition":
            return self.relative_distance(c, scope)
        if tag == "TraveledDistanceCondition":
            traveled = self.number(c, "value", scope)
            return lambda b: b.sb.TraveledDistanceCondition(traveled)
        if tag == "RelativeSpeedCondition":
            other = self.sumo_id(self.text(c, "entityRef", scope), c)
            value, rule = self.number(c, "value", scope), self.rule(c, scope)
            if rule not in ("greaterThan", "lessThan"):
                self.problems.add(c, f"rule '{rule}' (greaterThan and lessThan are)")
                return None

            def relative(b: Build) -> Any:
                # speed(ego) - speed(other) > v: SpeedDifferenceConditionFaster's set, held to `other`.
                diff = (
                    b.sb.SpeedDifferenceConditionFaster(value)
                    if rule == "greaterThan"
                    else b.sb.SpeedDifferenceConditionSlower(-value)
                )
                return b.sb.AndCondition(diff, b.sb.DistanceCondition(other, 1e9))

            return relative
        if tag == "TimeHeadwayCondition":
            return self.towards(c, scope, lambda b, v: b.sb.HeadwayCondition(v))
        if tag == "TimeToCollisionCondition":
            target = c.find("TimeToCollisionConditionTarget/EntityRef")
            if target is None:
                self.problems.add(c, "a target other than an entity")
                return None
            other = self.sumo_id(self.text(target, "entityRef", scope), target)
            value, rule = self.number(c, "value", scope), self.rule(c, scope)
            if rule not in ("lessThan", "lessOrEqual"):
                self.problems.add(c, f"rule '{rule}' (lessThan is)")
                return None
            return lambda b: b.sb.AndCondition(b.sb.TtcCondition(value), b.sb.DistanceCondition(other, 1e9))
        if tag == "CollisionCondition":
            ref = c.find("EntityRef")
            if ref is None:
                self.problems.add(c, "collision with a type of object")
                return None
            other = self.sumo_id(self.text(ref, "entityRef", scope), ref)
            return lambda b: b.sb.AndCondition(b.sb.CollisionCondition(), b.sb.DistanceCondition(other, 1e9))
        self.problems.add(c)
        return None

    def towards(self, c: Any, scope: Scope, make: Callable[[Build, float], Any]) -> Recipe | None:
        other = self.sumo_id(self.text(c, "entityRef", scope), c)
        value, rule = self.number(c, "value", scope), self.rule(c, scope)
        if rule not in ("lessThan", "lessOrEqual", "greaterThan", "greaterOrEqual"):
            self.problems.add(c, f"rule '{rule}'")
            return None

        def build(b: Build) -> Any:
            below = b.sb.AndCondition(make(b, value), b.sb.DistanceCondition(other, 1e9))
            return below if rule.startswith("less") else b.sb.NotCondition(below)

        return build

    def relative_distance(self, c: Any, scope: Scope) -> Recipe | None:
        other = self.sumo_id(self.text(c, "entityRef", scope), c)
        value, rule = self.number(c, "value", scope), self.rule(c, scope)
        kind = self.text(c, "relativeDistanceType", scope)
        kinds = {"longitudinal": "longitudinal", "lateral": "lateral", "cartesianDistance": "cartesian"}
        kinds["euclidianDistance"] = "cartesian"  # 1.0's name
        system = self.text(c, "coordinateSystem", scope, "entity")
        if kind not in kinds or system != "entity":
            self.problems.add(c, f"relativeDistanceType '{kind}' in coordinateSystem '{system}' (entity is)")
            return None
        freespace = self.text(c, "freespace", scope) == "true"
        return lambda b: b.sb.RelativeDistanceCondition(other, value, rule, kinds[kind], freespace)

    def distance(self, c: Any, scope: Scope) -> Recipe | None:
        value, rule = self.number(c, "value", scope), self.rule(c, scope)
        if rule not in ("lessThan", "lessOrEqual", "greaterThan", "greaterOrEqual"):
            self.problems.add(c, f"rule '{rule}'")
            return None
        kind = c.get("relativeDistanceType", "cartesianDistance")
        if kind not in ("cartesianDistance", "euclidianDistance"):
            self.problems.add(c, f"relativeDistanceType '{kind}' (cartesianDistance is)")
            return None
        if self.text(c, "freespace", scope, "false") == "true":
            self.problems.add(c, "freespace=true (distances are between front bumpers)")
            return None
        target: Any
        position = c.find("Position")
        entity = position.find("RelativeObjectPosition") if position is not None else None
        if position is not None and len(position) == 1 and position[0].tag == "EntityPosition":
            target = self.sumo_id(self.text(position[0], "entityRef", scope), position[0])
        elif entity is not None:
            self.problems.add(entity)
            return None
        else:
            lane, pos = self.position(position, scope, where(self.path, c))
            if lane is None:
                return None
            target = self.network.xy(lane, pos)

        def build(b: Build) -> Any:
            within = b.sb.DistanceCondition(target, value)
            return within if rule.startswith("less") else b.sb.NotCondition(within)

        return build


def _elements(root: Element) -> list[Element]:
    out = [root]
    for child in root.children:
        out += _elements(child)
    return out


def _compare(sb: Any, greater: Any, less: Any, value: float, rule: str) -> Any:
    if rule == "greaterThan":
        return greater(value)
    if rule == "lessThan":
        return less(value)
    if rule == "greaterOrEqual":
        return sb.NotCondition(less(value))
    if rule == "lessOrEqual":
        return sb.NotCondition(greater(value))
    if rule == "equalTo":
        return sb.AllCondition(sb.NotCondition(less(value)), sb.NotCondition(greater(value)))
    return sb.AnyCondition(less(value), greater(value))  # notEqualTo


def _compare_time(sb: Any, value: float, rule: str) -> Any:
    # TimeCondition(v) holds from v on; one nanosecond (SimTime's unit) later makes it strict.
    strictly_after = value + 1e-9
    if rule == "greaterThan":
        return sb.TimeCondition(strictly_after)
    if rule == "greaterOrEqual":
        return sb.TimeCondition(value)
    if rule == "lessThan":
        return sb.NotCondition(sb.TimeCondition(value))
    if rule == "lessOrEqual":
        return sb.NotCondition(sb.TimeCondition(strictly_after))
    if rule == "equalTo":
        return sb.TimeCondition(value, value)
    return sb.NotCondition(sb.TimeCondition(value, value))


def _as_stored(declared: Any, value: Any, what: str) -> Any:
    """`value` as ScenarioParameters keeps a parameter declared as `declared`: text, or a number."""
    if isinstance(declared, str):
        return str(value)
    if isinstance(declared, bool):
        return 1.0 if str(value).lower() in ("true", "1") else 0.0
    try:
        return float(value)
    except (TypeError, ValueError):
        raise ScenarioError(f"{what}: '{value}' is not a number") from None


def _compare_values(a: Any, b: Any, rule: str) -> bool:
    if isinstance(a, bool):  # a boolean parameter against "true"/"false"
        b = str(b).lower() in ("true", "1")
    try:
        x, y = float(a), float(b)
    except (TypeError, ValueError):
        x, y = str(a), str(b)  # type: ignore[assignment]
    return {
        "greaterThan": lambda: x > y,
        "lessThan": lambda: x < y,
        "equalTo": lambda: x == y,
        "greaterOrEqual": lambda: x >= y,
        "lessOrEqual": lambda: x <= y,
        "notEqualTo": lambda: x != y,
    }[rule]()


def read(path: Path, network: Network, overrides: Mapping[str, Any], binds: Mapping[str, str]) -> Scenario:
    """Reads and checks `path` (schema when available, then every element) on `network`."""
    tree = parse_file(path)
    validate(path, tree)
    xodr = logic_file(path)
    return Importer(path, network, overrides, binds, xodr if xodr is not None and xodr.is_file() else None).read(tree)


def logic_file(path: Path) -> Path | None:
    """The OpenDRIVE file the scenario names (RoadNetwork/LogicFile), if any."""
    tree = parse_file(path)
    logic = tree.getroot().find("RoadNetwork/LogicFile")
    if logic is None or not logic.get("filepath"):
        return None
    scope = Scope().declare(tree.getroot().find("ParameterDeclarations"), path)
    return (path.parent / str(scope.resolve(logic.get("filepath", ""), where(path, logic)))).resolve()
