# Types of the story API that sbsim provides to story scripts (implemented in C++).
from collections.abc import Iterable, Iterator, Sequence
from typing import Any, Literal, Protocol

import numpy as np
import numpy.typing as npt

__version__: str
IN_SBSIM: bool

class SimTime:
    def __init__(self, seconds: float | SimTime = 0.0) -> None: ...
    @property
    def seconds(self) -> float: ...
    def __float__(self) -> float: ...
    def __add__(self, other: Seconds) -> SimTime: ...
    def __radd__(self, other: Seconds) -> SimTime: ...
    def __sub__(self, other: Seconds) -> SimTime: ...
    def __rsub__(self, other: Seconds) -> SimTime: ...
    def __lt__(self, other: Seconds) -> bool: ...
    def __le__(self, other: Seconds) -> bool: ...
    def __gt__(self, other: Seconds) -> bool: ...
    def __ge__(self, other: Seconds) -> bool: ...

class Coord:
    """A point in Artery's canvas frame: x = x_sumo - xmin, y = ymax - y_sumo."""

    x: float
    y: float
    def __init__(self, x: float, y: float) -> None: ...

Seconds = SimTime | float | int
Point = Coord | tuple[float, float]

class RandomNumberGenerator:
    @property
    def index(self) -> int: ...
    def uniform(self, a: float = 0.0, b: float = 1.0) -> float: ...

RNG = RandomNumberGenerator

class Vehicle:
    """One vehicle of the current step's snapshot; reading it after that step raises ValueError."""

    id: str
    index: int
    x: float
    y: float
    position: tuple[float, float]
    speed: float
    angle: float
    acceleration: float
    length: float
    width: float
    max_speed: float
    road: str
    lane: str
    type: str
    time: float

class Snapshot:
    """All running vehicles after a step, ascending id order.

    Arrays are read-only copies (made on first access, safe to keep); the snapshot itself raises
    ValueError when read after its step.
    """

    time: float
    ids: list[str]
    positions: npt.NDArray[np.float64]  # shape (N, 2)
    speeds: npt.NDArray[np.float64]
    angles: npt.NDArray[np.float64]
    accelerations: npt.NDArray[np.float64]
    lengths: npt.NDArray[np.float64]
    widths: npt.NDArray[np.float64]
    max_speeds: npt.NDArray[np.float64]
    def __len__(self) -> int: ...
    def index_of(self, id: str) -> int | None: ...

class VehicleGoneError(RuntimeError):
    """A VehicleController used after its vehicle left the simulation."""

class VehicleController:
    """Commands one vehicle; may be kept, but raises VehicleGoneError once the vehicle has left."""

    id: str
    alive: bool
    type_id: str
    road_id: str
    lane_id: str
    lane_index: int
    speed: float
    max_speed: float
    speed_mode: int
    def set_max_speed(self, mps: float) -> None: ...
    def set_speed(self, mps: float) -> None: ...
    def slow_down(self, mps: float, seconds: float) -> None: ...
    def set_speed_mode(self, mode: int) -> None: ...
    def change_lane(self, lane_index: int, seconds: float) -> None: ...

class Condition:
    """Base of custom conditions: override test() or the vectorised test_all(). A subclass may
    name the snapshot columns it reads (``columns = ("position", "speed")``; also "angle",
    "acceleration", "lane", "size", "type", "max_speed"): the snapshot then reads no others for it."""

    columns: Sequence[str]
    def __init__(self) -> None: ...

class _CustomCondition(Protocol):
    def test(self, vehicle: Vehicle) -> bool | set[str]: ...
    def test_all(self, snapshot: Snapshot) -> npt.NDArray[np.bool_]: ...

class TimeCondition(Condition):
    def __init__(self, begin: Seconds, end: Seconds | None = None) -> None: ...

class SpeedConditionGreater(Condition):
    def __init__(self, mps: float) -> None: ...

class SpeedConditionLess(Condition):
    def __init__(self, mps: float) -> None: ...

class CarSetCondition(Condition):
    def __init__(self, ids: str | Iterable[str]) -> None: ...

class PolygonCondition(Condition):
    def __init__(self, points: Iterable[Point]) -> None: ...

class SpeedDifferenceConditionFaster(Condition):
    def __init__(self, delta: float, distance: float | None = None) -> None: ...

class SpeedDifferenceConditionSlower(Condition):
    def __init__(self, delta: float, distance: float | None = None) -> None: ...

class TtcCondition(Condition):
    def __init__(self, ttc: float, distance: float = 100.0) -> None: ...

class DistanceCondition(Condition):
    def __init__(self, target: Point | str, distance: float) -> None: ...

class StandstillCondition(Condition):
    def __init__(self, seconds: Seconds) -> None: ...

class AccelerationConditionGreater(Condition):
    def __init__(self, a: float) -> None: ...

class AccelerationConditionLess(Condition):
    def __init__(self, a: float) -> None: ...

class RoadCondition(Condition):
    def __init__(self, ids: str | Iterable[str]) -> None: ...

class LaneCondition(Condition):
    def __init__(self, ids: str | Iterable[str]) -> None: ...

class TypeCondition(Condition):
    def __init__(self, pattern: str) -> None: ...

class HeadwayCondition(Condition):
    def __init__(self, seconds: float) -> None: ...

class CollisionCondition(Condition):
    def __init__(self) -> None: ...

class TraveledDistanceCondition(Condition):
    """OpenSCENARIO's TraveledDistanceCondition: true once the vehicle drove at least ``distance`` m since it
    departed (SUMO's odometer; a scenario's entities depart at its start, so: since the start)."""

    distance: float
    def __init__(self, distance: float) -> None: ...

class TrafficSignalCondition(Condition):
    """OpenSCENARIO's TrafficSignalCondition: true while traffic light ``tls_id`` shows ``state`` (SUMO's
    letters, one per link), or with ``links`` while each of those links shows the one letter ``state``.
    Letters compare by colour (``G`` and ``g`` are both green). Read once per step; time-only."""

    tls_id: str
    state: str
    links: list[int]
    def __init__(self, tls_id: str, state: str, links: Sequence[int] = ...) -> None: ...

class RelativeDistanceCondition(Condition):
    """OpenSCENARIO's RelativeDistanceCondition: the distance from the vehicle to vehicle ``vehicle`` compared
    by ``rule`` (OpenSCENARIO's Rule names: lessThan, lessOrEqual, equalTo (within 0.01 m), greaterOrEqual,
    greaterThan, notEqualTo) with ``value`` m; yields {vehicle}. ``kind`` (relativeDistanceType) is measured
    in the vehicle's own frame: longitudinal along its heading, lateral across it, cartesian straight; between
    the centres (reference points) or, ``freespace=True``, between the outlines (0 when they overlap)."""

    vehicle: str
    value: float
    rule: str
    kind: str
    freespace: bool
    def __init__(
        self,
        vehicle: str,
        value: float,
        rule: Literal["lessThan", "lessOrEqual", "equalTo", "greaterOrEqual", "greaterThan", "notEqualTo"] = "lessThan",
        kind: Literal["longitudinal", "lateral", "cartesian"] = "cartesian",
        freespace: bool = False,
    ) -> None: ...

class PositionDistanceCondition(Condition):
    """OpenSCENARIO's DistanceCondition to a position: the distance from the vehicle to ``point`` (SUMO x, y)
    compared by ``rule`` with ``value`` m, measured as RelativeDistanceCondition measures (``kind`` in the
    vehicle's frame; from its centre or, ``freespace=True``, from its outline)."""

    value: float
    freespace: bool
    def __init__(
        self,
        point: Coord | tuple[float, float],
        value: float,
        rule: Literal["lessThan", "lessOrEqual", "equalTo", "greaterOrEqual", "greaterThan", "notEqualTo"] = "lessThan",
        kind: Literal["longitudinal", "lateral", "cartesian"] = "cartesian",
        freespace: bool = False,
    ) -> None: ...

class AndCondition(Condition):
    def __init__(self, a: Condition, b: Condition) -> None: ...

class OrCondition(Condition):
    def __init__(self, a: Condition, b: Condition) -> None: ...

class NotCondition(Condition):
    def __init__(self, condition: Condition) -> None: ...

class AllCondition(Condition):
    def __init__(self, *conditions: Condition) -> None: ...

class AnyCondition(Condition):
    def __init__(self, *conditions: Condition) -> None: ...

class DenmCondition(Condition):
    """A vehicle whose DENM memory holds a live event of `cause` (any if None) heard at most
    `max_age` ago, the event at most `within` m away, `ahead` in its driving direction, the vehicle
    `in_relevance_area` of the event; yields the events' originating vehicles."""

    def __init__(
        self,
        cause: int | None = None,
        max_age: Seconds | None = None,
        within: float | None = None,
        ahead: bool = False,
        in_relevance_area: bool = False,
    ) -> None: ...
    def describe(self) -> str: ...

class CamCondition(Condition):
    """A vehicle whose local dynamic map knows a station (from its CAMs) within `distance` m,
    its CAM at most `max_age` old; yields those stations."""

    def __init__(self, distance: float | None = None, max_age: Seconds | None = None) -> None: ...
    def describe(self) -> str: ...

class EquippedCondition(Condition):
    """A vehicle that carries V2X equipment (the run's --penetration draw; everyone at the default 1)."""

    def __init__(self) -> None: ...

class HoldCondition(Condition):
    def __init__(self, condition: Condition, seconds: Seconds) -> None: ...

class RisingCondition(Condition):
    def __init__(self, condition: Condition) -> None: ...

class LatchCondition(Condition):
    def __init__(self, condition: Condition) -> None: ...

class EntityCondition(Condition):
    """The operand asked about one named vehicle, whichever vehicle the story is evaluated for."""

    def __init__(self, vehicle: str, condition: Condition) -> None: ...

class TriggeringEntitiesCondition(Condition):
    """OpenSCENARIO's ByEntityCondition: each EntityCondition (one per triggering entity) evaluated every
    time; true when any (``rule="all"``: every one) holds, its others the entities it holds for (the
    triggering entities a ManeuverGroup with selectTriggeringEntities takes as actors)."""

    def __init__(self, entities: Sequence[EntityCondition], rule: Literal["any", "all"] = "any") -> None: ...

class ElementCondition(Condition):
    """True while an element of a ScenarioMachine runs (for its actors, or the world); when its
    ManeuverGroup selects triggering entities, also for the entities that started its act."""

    def __init__(self, machine: ScenarioMachine, element: int, actors: str | Iterable[str] | None = None) -> None: ...

class ElementStateCondition(Condition):
    """OpenSCENARIO's StoryboardElementStateCondition on a ScenarioMachine element."""

    def __init__(self, machine: ScenarioMachine, element: int, state: str) -> None: ...

class LimitCondition(Condition):
    def __init__(self, n: int) -> None: ...

class LikelihoodCondition(Condition):
    def __init__(self, rng: RandomNumberGenerator, p: float) -> None: ...

class DeferringCondition(Condition):
    def __init__(self, rng: RandomNumberGenerator, min: Seconds, max: Seconds) -> None: ...

class Effect:
    """Base of custom effects: override apply(self, vehicle) and remove(self, vehicle)."""

    def __init__(self) -> None: ...

class SpeedEffect(Effect):
    speed: float
    over: float
    def __init__(self, mps: float, over: Seconds | None = None) -> None: ...

class StopEffect(Effect):
    def __init__(self) -> None: ...

class SetSpeedEffect(Effect):
    """Once, at activation: the vehicle drives at `mps` from then on (SUMO's setSpeed)."""

    def __init__(self, mps: float) -> None: ...
    @property
    def speed(self) -> float: ...

class EmergencyStopEffect(Effect):
    def __init__(self) -> None: ...

class SignalEffect(Effect):
    cause: str
    on_exit: str | None
    def __init__(self, cause: str, on_exit: str | None = None) -> None: ...

class SpeedFactorEffect(Effect):
    factor: float
    def __init__(self, factor: float) -> None: ...

class TypeEffect(Effect):
    type_id: str
    def __init__(self, type_id: str) -> None: ...

class ColorEffect(Effect):
    color: tuple[int, int, int, int]
    def __init__(self, color: tuple[int, int, int] | tuple[int, int, int, int]) -> None: ...

class LaneEffect(Effect):
    lane_index: int
    def __init__(self, lane_index: int) -> None: ...

class RouteEffect(Effect):
    """Routes the vehicle while the story is active (to ``target_edge``, or to its destination through
    ``via``); after, to the destination it had. ``keep=True`` (OpenSCENARIO's RoutingAction): routed once at
    activation through ``via`` to ``target_edge`` (default: its destination; both may be given) and kept;
    complete at once, a route SUMO cannot find ends the run (exit code 2)."""

    target_edge: str | None
    via: list[str]
    keep: bool
    def __init__(
        self, target_edge: str | None = None, *, via: Iterable[str] | None = None, keep: bool = False
    ) -> None: ...

class TeleportEffect(Effect):
    """OpenSCENARIO's TeleportAction in an event: puts the vehicle at ``position`` m on lane ``lane`` of
    ``edge`` at once (SUMO's moveTo; it keeps its speed), or, with ``relative_to``, ``lane`` lanes to the
    left of that vehicle's lane and ``position`` m ahead of it as it is at activation. A target off the
    vehicle's route is routed to first (changeTarget); after that move it drives on along ``onward``
    (edges from the target edge) if given, else to its destination. Complete at once."""

    edge: str | None
    lane: int
    position: float
    relative_to: str | None
    onward: list[str]
    def __init__(
        self,
        edge: str | None = None,
        lane: int = 0,
        position: float = 0.0,
        *,
        relative_to: str | None = None,
        onward: Iterable[str] | None = None,
    ) -> None: ...

#: OpenSCENARIO's TransitionDynamics: dynamicsShape and dynamicsDimension.
_TransitionShape = Literal["step", "linear", "cubic", "sinusoidal"]
_TransitionDimension = Literal["time", "distance", "rate"]

class SpeedChangeEffect(Effect):
    """OpenSCENARIO's SpeedAction: from the vehicle's speed at activation to the target along
    TransitionDynamics (``shape``, ``dimension``, ``value``: s for time, m driven for distance, m/s² for
    rate, the change taking |Δv| / rate s), commanded each step (SUMO's setSpeed), the target held after while
    the story is active; then SUMO has the speed again. The target (SpeedActionTarget) is ``target`` m/s
    (AbsoluteTargetSpeed) or, with ``relative_to`` (RelativeTargetSpeed's entityRef), that vehicle's speed
    plus ``target`` m/s (``value_type="delta"``) or times ``target`` (``"factor"``), read at activation or,
    ``continuous=True``, every step. Exact by default (SUMO's acceleration bounds and safe speed off, the
    speed limit disregarded; the vehicle's max speed and any SpeedEffect cap still hold); ``safe_gap=True``
    keeps SUMO's safe gap to the leader, which also bounds the change to the vehicle's accel/decel. A
    StopEffect or EmergencyStopEffect rules over it while active. ``keep=True``: once the change ran, the
    vehicle keeps the target after the story ends (SUMO's setSpeed, as SetSpeedEffect), as an OpenSCENARIO
    entity does. As a ScenarioMachine action it is complete when the change ran (continuous: never).
    Domain "speed"."""

    target: float
    shape: str
    dimension: str
    value: float
    relative_to: str | None
    value_type: str
    continuous: bool
    safe_gap: bool
    keep: bool
    def __init__(
        self,
        target: float,
        shape: _TransitionShape = "step",
        dimension: _TransitionDimension = "time",
        value: float = 0.0,
        *,
        relative_to: str | None = None,
        value_type: Literal["delta", "factor"] = "delta",
        continuous: bool = False,
        safe_gap: bool = False,
        keep: bool = False,
    ) -> None: ...

class LaneChangeEffect(Effect):
    """OpenSCENARIO's LaneChangeAction: a lateral manoeuvre from where the vehicle is at activation to the
    centre of the target lane plus ``offset`` m (targetLaneOffset; positive to the left) along
    LaneChangeActionDynamics (``shape``, ``dimension``: time s, distance m driven, or rate m/s across),
    moved each step through SUMO's sublane model (changeSublane; the run needs ``--lateral-resolution``, else
    exit code 2), and held while the story is active with SUMO's own lane changes off; then SUMO's lane-change
    model decides again. The target lane (LaneChangeTarget) is ``lane``, SUMO's index from the right
    (AbsoluteTargetLane, mapped to SUMO's index), or ``lane`` lanes to the left (negative: right) of the
    vehicle's own lane (``relative=True``) or of vehicle ``relative_to``'s lane at activation
    (RelativeTargetLane). Domain "lane"."""

    lane: int
    shape: str
    dimension: str
    value: float
    relative: bool
    relative_to: str | None
    offset: float
    def __init__(
        self,
        lane: int,
        shape: _TransitionShape = "step",
        dimension: _TransitionDimension = "time",
        value: float = 0.0,
        *,
        relative: bool = False,
        relative_to: str | None = None,
        offset: float = 0.0,
    ) -> None: ...

class LaneOffsetEffect(Effect):
    """OpenSCENARIO's LaneOffsetAction (AbsoluteTargetLaneOffset): the vehicle moves ``offset`` m (positive to
    the left) off the centre of the lane it is on at activation with ``shape`` over ``duration`` s or, as
    LaneOffsetActionDynamics gives it, within ``max_lateral_acc`` m/s² (cubic: T = sqrt(6 d / a), sinusoidal:
    T = pi sqrt(d / (2 a)), linear as cubic), each step through SUMO's sublane model, and holds it while the
    story is active; then SUMO aligns the vehicle again. ``relative_to`` (RelativeTargetLaneOffset): ``offset``
    m off that vehicle's own offset at activation. ``continuous=True``: held until the story ends, so as a
    ScenarioMachine action it is never complete (its event runs until stopped). Domain "lane"."""

    offset: float
    shape: str
    duration: float | None
    max_lateral_acc: float | None
    relative_to: str | None
    continuous: bool
    def __init__(
        self,
        offset: float,
        shape: _TransitionShape = "step",
        *,
        duration: float | None = None,
        max_lateral_acc: float | None = None,
        relative_to: str | None = None,
        continuous: bool = False,
    ) -> None: ...

EffectFactory = Effect
SpeedEffectFactory = SpeedEffect
StopEffectFactory = StopEffect
SignalEffectFactory = SignalEffect

class Story:
    name: str
    activations: int
    max_activations: int | None
    def __init__(
        self,
        condition: Condition,
        effects: Iterable[Effect] | None = None,
        name: str | None = None,
        max_activations: int | None = None,
    ) -> None: ...

class WorldStory(Story):
    """A story about the network: a time-only condition, evaluated once per step; world effects."""

    def __init__(
        self,
        condition: Condition,
        effects: Iterable[WorldEffect] | None = None,
        name: str | None = None,
    ) -> None: ...

class WorldEffect:
    """Base of the effects on the network a WorldStory takes."""

class CloseRoadEffect(WorldEffect):
    edge_ids: list[str]
    def __init__(self, edge_ids: str | Iterable[str]) -> None: ...

class SpawnEffect(WorldEffect):
    id: str
    def __init__(
        self,
        id: str,
        route: str | Iterable[str] | None = None,
        from_edge: str | None = None,
        to_edge: str | None = None,
        type: str | None = None,
        lane: int | str | None = None,
        position: float | str | None = None,
        speed: float | str | None = None,
    ) -> None: ...

class TrafficLightEffect(WorldEffect):
    """Holds traffic light ``tls_id`` at ``state`` (SUMO's letters, one per link) while the story is active,
    then its programme resumes. With ``links``, ``state`` is one letter for those links (the others keep
    what they show at activation); with ``keep``, the hold outlasts the story until a later hold of the light."""

    tls_id: str
    state: str
    links: list[int]
    keep: bool
    def __init__(self, tls_id: str, state: str, links: Sequence[int] = ..., keep: bool = False) -> None: ...

class TrafficLightPhaseEffect(WorldEffect):
    """Switches traffic light ``tls_id``'s programme to phase ``phase`` when the story activates (its full
    duration, then on as programmed), ending every hold of the light; the story's end changes nothing."""

    tls_id: str
    phase: int
    def __init__(self, tls_id: str, phase: int) -> None: ...

class Parameters:
    """The run's study parameters (--param NAME=VALUE), read-only; values are bool, int, float or str."""

    def __getitem__(self, name: str) -> bool | int | float | str: ...
    def get(self, name: str, default: object = None) -> object: ...
    def __contains__(self, name: str) -> bool: ...
    def __len__(self) -> int: ...
    def __iter__(self) -> Iterator[str]: ...
    def keys(self) -> list[str]: ...
    def items(self) -> list[tuple[str, bool | int | float | str]]: ...

class _RunRecord(Protocol):  # what a custom Criterion.evaluate(run) receives
    events: list[dict[str, Any]]  # the event log's lines
    statistics: dict[str, dict[str, float]]  # per name: count, sum, mean, min, max
    activations: dict[str, int]  # per story

class Criterion:
    """Base of custom criteria: override evaluate(self, run) -> bool | (passed, actual, expected); run.events is
    the event log (dicts), run.statistics the aggregates per name, run.activations per story."""

    name: str
    def __init__(self) -> None: ...

class NoCollision(Criterion):
    def __init__(self) -> None: ...

class MaxSpeed(Criterion):
    def __init__(
        self, mps: float, vehicles: str | Iterable[str] | None = None, equipped_only: bool = False
    ) -> None: ...

class ReachedRegion(Criterion):
    def __init__(self, vehicle: str, area: Iterable[Point], by: Seconds) -> None: ...

class KeepsLane(Criterion):
    def __init__(self, vehicles: str | Iterable[str] | None = None, equipped_only: bool = False) -> None: ...

class NoRedLightRunning(Criterion):
    def __init__(self, vehicles: str | Iterable[str] | None = None, equipped_only: bool = False) -> None: ...

class StoryActivated(Criterion):
    def __init__(self, story: str, at_least: int = 1) -> None: ...

class WarnedBefore(Criterion):
    """Every vehicle that reached the place (an edge id, or an area of points) between `since` and `until` had
    heard a DENM of `cause` (any if None) at least `seconds` before; needs a DEN service (--services).
    With `equipped_only`, only the V2X-equipped vehicles are judged."""

    def __init__(
        self,
        area_or_edge: str | Iterable[Point],
        cause: int | None = None,
        seconds: Seconds = 0,
        since: Seconds = 0,
        until: Seconds | None = None,
        equipped_only: bool = False,
    ) -> None: ...

class Storyboard:
    stories: list[Story]
    warmup_end_time: SimTime
    def registerStory(self, story: Story) -> None: ...
    def registerCriterion(self, criterion: Criterion, name: str | None = None) -> None: ...
    def register_criterion(self, criterion: Criterion, name: str | None = None) -> None: ...
    def register_story(self, story: Story) -> None: ...
    def getRandomNumberGenerator(self, k: int = 0) -> RandomNumberGenerator: ...
    def random_generator(self, k: int = 0) -> RandomNumberGenerator: ...
    @property
    def parameters(self) -> Parameters: ...
    def parameter(self, name: str, default: object = None) -> object: ...
    def getWarmupEndTime(self) -> SimTime: ...
    def convertTraciPosition(self, x: float, y: float) -> Coord: ...
    def convert_traci_position(self, x: float, y: float) -> Coord: ...
    # A row of the run's statistics (--statistics) at the current time; aggregated per name in the summary.
    def record(self, name: str, value: float, *, vehicle: str | None = None, story: str | None = None) -> None: ...

# The shape of a polygon SUMO loaded (a <poly> of the sumocfg's additional files), SUMO frame.
def sumo_polygon(poly_id: str) -> list[tuple[float, float]]: ...
def all_of(*conditions: Condition) -> Condition: ...
def any_of(*conditions: Condition) -> Condition: ...
def once(condition: Condition) -> LatchCondition: ...
def seconds(x: float) -> SimTime: ...
def milliseconds(x: float) -> SimTime: ...

_TriggerCondition = tuple[str, Condition, str, float]

class ScenarioMachine:
    """OpenSCENARIO 1.2's storyboard state machine (Storyboard, Story, Act, ManeuverGroup, Maneuver,
    Event); ElementCondition stories show its elements. Its storyboard's stop trigger ends the run."""

    def __init__(self) -> None: ...
    def add(
        self,
        name: str,
        kind: str,
        parent: int | None = None,
        start: Sequence[Sequence[_TriggerCondition]] | None = None,
        stop: Sequence[Sequence[_TriggerCondition]] | None = None,
        max_executions: int = 1,
        priority: str = "parallel",
        select_triggering_entities: bool = False,
    ) -> int:
        """``max_executions`` of an event or a maneuver group (which then runs again, its events as new);
        ``select_triggering_entities`` (a maneuver group): the entities that started its act are actors."""
    def add_action(self, event: int, action: Effect) -> None:
        """The event ends only once this effect (applied by its story) is complete: a transition
        when it reached its target, a one-shot effect at once."""
    def __len__(self) -> int: ...
    def state(self, element: int) -> str: ...
    def executions(self, element: int) -> int: ...
    def triggering_entities(self, element: int) -> list[str]:
        """The entities that fired the element's start trigger when it last started."""
    @property
    def ended(self) -> bool: ...

class ScenarioParameters:
    """An OpenSCENARIO storyboard's global parameters while it runs (numbers, true as 1, or texts)."""

    def __init__(self) -> None: ...
    def declare(self, name: str, value: float | str) -> None: ...
    def __contains__(self, name: str) -> bool: ...
    def get(self, name: str) -> float | str: ...

class ParameterCondition(Condition):
    """OpenSCENARIO's ParameterCondition: the parameter compares to `value` by `rule` now."""

    def __init__(self, parameters: ScenarioParameters, name: str, rule: str, value: float | str) -> None: ...

class ParameterEffect(WorldEffect):
    """Once, at activation: the parameter is set to `value`, or has it added or multiplied in."""

    def __init__(self, parameters: ScenarioParameters, name: str, op: str, value: float | str) -> None: ...

class RemoveVehicleEffect(WorldEffect):
    """Once, at activation: the vehicle leaves the simulation (OpenSCENARIO's DeleteEntityAction)."""

    def __init__(self, id: str) -> None: ...
    @property
    def id(self) -> str: ...
