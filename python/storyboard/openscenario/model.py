"""What the importer makes of an OpenSCENARIO file: entities, their initial state, and the storyboard
as a tree of elements whose triggers and actions are recipes for storyboard conditions and effects
(built inside sbsim by :mod:`.stories`)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .network import Lane, Network


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
    obstacle: bool = False  # a MiscObject: a vehicle held at speed 0 wherever it is put

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
    acquire: tuple[str, list[str]] | None = None  # AcquirePositionAction: (target edge, via edges)


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
    select_triggering: bool = False  # a maneuver group's actors include its act's triggering entities
    actions: list[Action] = field(default_factory=list)


@dataclass
class Scenario:
    path: Path
    network: Network
    entities: dict[str, Entity]
    starts: list[Start]
    storyboard: Element
    parameters: dict[str, Any]  # the global ones
