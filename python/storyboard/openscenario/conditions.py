"""Triggers (OR of AND condition groups) and their conditions as recipes for sbsim conditions."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from .errors import ScenarioError, where
from .model import Build, Recipe, Trigger, TriggerCondition
from .parameters import Scope, as_stored
from .reader import Reader
from .signals import phase_state, signal_links, signal_state

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


class ConditionReader(Reader):
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
                value = as_stored(self.globals[ref], self.value(c, "value", scope), where(self.path, c))
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
        if c.tag == "TrafficSignalCondition":
            here = where(self.path, c)
            tls, links = signal_links(self.network, self.text(c, "name", scope), here)
            state = signal_state(self.network, tls, links, self.text(c, "state", scope), here)
            return lambda b: b.sb.TrafficSignalCondition(tls, state, links)
        if c.tag == "TrafficSignalControllerCondition":
            # The controller is a SUMO traffic light; its phase holds while the light shows the
            # phase's state (phases of one state are not told apart).
            here = where(self.path, c)
            tls = self.text(c, "trafficSignalControllerRef", scope)
            state = phase_state(self.network, tls, self.text(c, "phase", scope), here)
            return lambda b: b.sb.TrafficSignalCondition(tls, state)
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
            # Each entity's own condition; the result names the entities it holds for (the
            # triggering entities, which a ManeuverGroup with selectTriggeringEntities takes as actors).
            parts = [b.sb.EntityCondition(i, make(b)) for i in ids]
            return b.sb.TriggeringEntitiesCondition(parts, "all" if rule_all else "any")

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
        if tag == "OffroadCondition":
            self.problems.add(c, "a SUMO vehicle is never off the road (it drives on lanes only), so it never holds")
            return None
        if tag == "EndOfRoadCondition":
            self.problems.add(
                c, "a SUMO vehicle at the end of its road arrives and leaves the simulation; it never stands there"
            )
            return None
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
        kinds = {"longitudinal": "longitudinal", "lateral": "lateral", "cartesianDistance": "cartesian"}
        kinds["euclidianDistance"] = "cartesian"  # 1.1's name
        kind = self.text(c, "relativeDistanceType", scope, "cartesianDistance")
        system = self.text(c, "coordinateSystem", scope, "entity")
        if kind not in kinds or system != "entity":
            self.problems.add(c, f"relativeDistanceType '{kind}' in coordinateSystem '{system}' (entity is)")
            return None
        freespace = self.text(c, "freespace", scope, "false") == "true"
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
        measure = kinds[kind]
        if measure != "cartesian" or freespace:
            # In the entity's frame, from its centre or outline, as RelativeDistanceCondition measures.
            if isinstance(target, str):
                return lambda b: b.sb.RelativeDistanceCondition(target, value, rule, measure, freespace)
            return lambda b: b.sb.PositionDistanceCondition(target, value, rule, measure, freespace)
        if rule not in ("lessThan", "lessOrEqual", "greaterThan", "greaterOrEqual"):
            self.problems.add(c, f"rule '{rule}' (a cartesian distance between reference points takes <, <=, >, >=)")
            return None

        def build(b: Build) -> Any:
            within = b.sb.DistanceCondition(target, value)
            return within if rule.startswith("less") else b.sb.NotCondition(within)

        return build


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
