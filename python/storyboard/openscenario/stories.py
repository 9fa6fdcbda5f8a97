"""Builds a scenario's stories inside sbsim (the generated story script calls create()).

One ScenarioMachine holds the storyboard's states. Stories, named for the OpenSCENARIO element:
- "Storyboard" (a WorldStory): active while the storyboard runs (its stop trigger's conditions);
- "Init": spawns the positioned entities at the first step; "Init/<entity>" sets an Init speed and
  routes it to the position of an Init AcquirePositionAction; "Init/<entity> (obstacle)" holds a
  MiscObject at speed 0 (StopEffect) for as long as it runs;
- "<Story>/<Act>" (a WorldStory): active while the act runs;
- "<Story>/<Act>/<Event>": active for the event's actors while the event runs (the step it starts,
  and until its transitions reached their targets), with its actions as effects (a world one, an
  AddEntityAction, in "<Story>/<Act>/<Event> (world)").
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

import storyboard as sb

from .errors import ScenarioError
from .network import Network
from .scenario import Build, Element, Trigger, read


class _BoardParameters(Mapping[str, Any]):
    """The run's --param values, each read through board.parameter() (so sbsim knows it was used)."""

    def __init__(self, board: Any) -> None:
        self.board = board

    def __getitem__(self, name: str) -> Any:
        if name not in self.board.parameters:
            raise KeyError(name)
        return self.board.parameter(name)

    def __iter__(self) -> Iterator[str]:
        return iter(self.board.parameters)

    def __len__(self) -> int:
        return len(self.board.parameters)


def _walk(element: Element) -> Iterator[tuple[Element, Element | None]]:
    stack: list[tuple[Element, Element | None]] = [(element, None)]
    while stack:
        e, parent = stack.pop(0)
        yield e, parent
        stack[0:0] = [(c, e) for c in e.children]


def _trigger(trigger: Trigger, build: Build) -> list[list[tuple[str, Any, str, float]]]:
    return [[(c.name, c.recipe(build), c.edge, c.delay) for c in group] for group in trigger]


def create(board: Any, xosc: str, net: str, binds: Mapping[str, str]) -> sb.ScenarioMachine:
    scenario = read(Path(xosc), Network.read(Path(net)), _BoardParameters(board), binds)
    machine = sb.ScenarioMachine()
    params = sb.ScenarioParameters()
    for name, value in scenario.parameters.items():
        params.declare(name, value)
    build = Build(sb, machine, {}, params)
    elements = list(_walk(scenario.storyboard))
    # Indices first, so that a StoryboardElementStateCondition may name any element.
    for n, (e, _) in enumerate(elements):
        build.index.setdefault((e.kind, e.name), n)
    # The storyboard starts when its Init is done: every entity it puts on the road (or binds) runs.
    on_road = [
        scenario.entities[s.entity].sumo_id
        for s in scenario.starts
        if s.lane is not None or scenario.entities[s.entity].bound
    ]
    on_road += [e.sumo_id for e in scenario.entities.values() if e.bound and e.sumo_id not in on_road]
    if on_road:
        init = [sb.EntityCondition(v, sb.TimeCondition(0)) for v in on_road]
        ready = init[0] if len(init) == 1 else sb.AllCondition(*init)
        start_trigger = [[("Init done", ready, "none", 0.0)]]
    else:
        start_trigger = []
    indices: dict[int, int] = {}
    for e, parent in elements:
        indices[id(e)] = machine.add(
            e.name,
            e.kind,
            parent=None if parent is None else indices[id(parent)],
            start=start_trigger if parent is None else _trigger(e.start, build),
            stop=_trigger(e.stop, build),
            max_executions=e.max_executions,
            priority=e.priority,
            select_triggering_entities=e.kind == "maneuver_group" and e.select_triggering,
        )

    board.registerStory(sb.WorldStory(sb.ElementCondition(machine, 0), [], name="Storyboard"))
    spawns = []
    for s in scenario.starts:
        entity = scenario.entities[s.entity]
        if not entity.bound and s.lane is not None:
            route = s.route or scenario.network.follow(s.lane)
            if route[0] != s.lane.edge:
                route = [s.lane.edge, *route]
            spawns.append(
                sb.SpawnEffect(
                    entity.sumo_id,
                    route=route,
                    type=entity.vtype,
                    lane=s.lane.index,
                    position=s.pos,
                    speed=s.speed if s.speed is not None else 0,
                )
            )
    if spawns:
        board.registerStory(sb.WorldStory(sb.TimeCondition(0), spawns, name="Init"))
    for s in scenario.starts:
        effects = [] if s.speed is None else [sb.SetSpeedEffect(s.speed)]
        if s.acquire is not None:  # routed once, when it is on the road
            effects.append(sb.RouteEffect(s.acquire[0], via=s.acquire[1], keep=True))
        if effects:
            entity = scenario.entities[s.entity]
            board.registerStory(sb.Story(sb.CarSetCondition(entity.sumo_id), effects, name=f"Init/{s.entity}"))
    for entity in scenario.entities.values():
        if entity.obstacle:
            board.registerStory(
                sb.Story(sb.CarSetCondition(entity.sumo_id), [sb.StopEffect()], name=f"Init/{entity.name} (obstacle)")
            )
    names: set[str] = set()
    for e, _ in elements:
        if e.kind == "act":
            board.registerStory(sb.WorldStory(sb.ElementCondition(machine, indices[id(e)]), [], name=e.path))
        if e.kind != "event":
            continue
        name = e.path if e.path not in names else f"{e.path}#{indices[id(e)]}"
        names.add(name)
        # Actors: the group's, and (selectTriggeringEntities) those that started its act, known at run time.
        acting = bool(e.actors) or e.select_triggering
        if not acting and any(not a.world for a in e.actions):
            raise ScenarioError(f"{xosc}: event '{e.path}' acts on vehicles, but its ManeuverGroup has no actors")
        world = [a.recipe(build) for a in e.actions if a.world]
        private = [a.recipe(build) for a in e.actions if not a.world]
        for effect in private:  # the event ends once each is complete (a transition: its target reached)
            machine.add_action(indices[id(e)], effect)
        if world:
            board.registerStory(
                sb.WorldStory(sb.ElementCondition(machine, indices[id(e)]), world, name=f"{name} (world)")
            )
        if private or not world:
            condition = sb.ElementCondition(machine, indices[id(e)], e.actors or None)
            if acting:
                board.registerStory(sb.Story(condition, private, name=name))
            else:
                board.registerStory(sb.WorldStory(condition, [], name=name))
    return machine
