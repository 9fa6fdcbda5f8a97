"""Event actions as recipes for sbsim effects: speed, lane change, lane offset, teleport, routing
(assign route, acquire position), add/delete entity, parameter set/modify, and sbsim's SignalEffect
as a CustomCommandAction."""

from __future__ import annotations

from typing import Any

from .errors import ScenarioError, where
from .model import Action, Build
from .parameters import Scope, as_stored
from .reader import Reader
from .signals import phase_index, signal_links, signal_state

SHAPES = ("step", "linear", "cubic", "sinusoidal")
DIMENSIONS = ("time", "distance", "rate")


class ActionReader(Reader):
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
            if inner.tag == "TeleportAction":
                return self.read_teleport(inner, scope, name)
            if inner.tag == "RoutingAction" and len(inner) == 1:
                return self.read_routing(inner[0], scope, name)
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
        if kind.tag == "GlobalAction" and kind.find("InfrastructureAction/TrafficSignalAction") is not None:
            return self.read_traffic_signal_action(kind.find("InfrastructureAction/TrafficSignalAction"), scope, name)
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
            op, operand = "set", as_stored(self.globals[ref], self.value(action[0], "value", scope), here)
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

    def transition(self, dynamics: Any, scope: Scope, follow: bool = False) -> tuple[str, str, float] | None:
        """TransitionDynamics as (shape, dimension, value); None (a problem) for what sbsim lacks.
        `follow`: the caller can honour followingMode 'follow' (else only 'position' is read)."""
        shape = self.text(dynamics, "dynamicsShape", scope)
        dimension = self.text(dynamics, "dynamicsDimension", scope, "time")
        if shape not in SHAPES or dimension not in DIMENSIONS:
            self.problems.add(dynamics, f"dynamicsShape '{shape}' with dynamicsDimension '{dimension}'")
            return None
        mode = self.text(dynamics, "followingMode", scope, "position")
        if mode not in ("position", "follow") or (mode == "follow" and not follow):
            self.problems.add(
                dynamics,
                f"followingMode '{mode}' here (a lateral manoeuvre follows its shape exactly: SUMO's sublane "
                "model has no own lateral dynamics to follow it with)",
            )
            return None
        return shape, dimension, self.number(dynamics, "value", scope, "0")

    def follows(self, dynamics: Any, scope: Scope) -> bool:
        """followingMode 'follow': the entity follows the shape within its own dynamics."""
        return self.text(dynamics, "followingMode", scope, "position") == "follow"

    def read_speed(self, speed: Any, scope: Scope, name: str) -> Action | None:
        dynamics = speed.find("SpeedActionDynamics")
        target = speed.find("SpeedActionTarget")
        if dynamics is None or target is None or len(target) != 1:
            self.problems.add(speed, "a SpeedAction needs SpeedActionDynamics and a SpeedActionTarget")
            return None
        law = self.transition(dynamics, scope, follow=True)
        if law is None:
            return None
        shape, dimension, by = law
        # followingMode 'follow': SUMO keeps the safe gap, which bounds the change to the entity's
        # acceleration and deceleration (its own dynamics); 'position': the shape exactly.
        gap = self.follows(dynamics, scope)
        inner = target[0]
        if inner.tag == "AbsoluteTargetSpeed":
            value = self.number(inner, "value", scope)
            if shape == "step":
                # At once, within SUMO's safety checks (its acceleration bounds), kept after.
                return Action(name, False, f"SetSpeedEffect({value:g} m/s)", lambda b: b.sb.SetSpeedEffect(value))

            def absolute(b: Build) -> Any:
                return b.sb.SpeedChangeEffect(value, shape, dimension, by, safe_gap=gap, keep=True)

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
                    value,
                    shape,
                    dimension,
                    by,
                    relative_to=other,
                    value_type=kind,
                    continuous=continuous,
                    safe_gap=gap,
                    keep=True,
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
        shape, dimension, by = law  # by rate: m/s across the road, so it takes |lateral distance| / rate s
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
        target = action.find("LaneOffsetTarget")
        target = target[0] if target is not None and len(target) == 1 else None
        if dynamics is None or target is None:
            self.problems.add(action, "a LaneOffsetAction needs its dynamics and a LaneOffsetTarget")
            return None
        # continuous: the offset is held while the event runs (it ends only when stopped).
        continuous = self.text(action, "continuous", scope, "false") == "true"
        other: str | None = None
        if target.tag == "RelativeTargetLaneOffset":
            other = self.sumo_id(self.text(target, "entityRef", scope), target)
            if continuous:
                self.problems.add(
                    action, "continuous=true with a RelativeTargetLaneOffset (the other's offset is read at the start)"
                )
                return None
        elif target.tag != "AbsoluteTargetLaneOffset":
            self.problems.add(target)
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
        what = f"{other}'s offset {offset:+g} m" if other else f"{offset:+g} m"
        return Action(
            name,
            False,
            f"LaneOffsetEffect({what}{', held' if continuous else ''})",
            lambda b: b.sb.LaneOffsetEffect(
                offset, shape, max_lateral_acc=acc, relative_to=other, continuous=continuous
            ),
        )

    # -- teleport and routing -----------------------------------------------------------------
    def read_teleport(self, action: Any, scope: Scope, name: str) -> Action | None:
        position = action.find("Position")
        here = where(self.path, action)
        if position is not None and len(position) == 1 and position[0].tag == "RelativeLanePosition":
            # Relative to where the other entity is when the event starts (not to its Init place).
            p = position[0]
            other = self.sumo_id(self.text(p, "entityRef", scope), p)
            if abs(self.number(p, "offset", scope, "0")) > 1e-9 or p.get("dsLane") is not None:
                self.problems.add(p, "a lateral offset or dsLane")
                return None
            d_lane = int(self.number(p, "dLane", scope))
            ds = self.number(p, "ds", scope, "0")
            return Action(
                name,
                False,
                f"TeleportEffect({other}'s lane {d_lane:+d}, {ds:+g} m)",
                lambda b: b.sb.TeleportEffect(lane=d_lane, position=ds, relative_to=other),
            )
        lane, pos = self.position(position, scope, here)
        if lane is None:
            return None
        onward = self.onward(lane)
        return Action(
            name,
            False,
            f"TeleportEffect({lane.id} at {pos:g} m)",
            lambda b: b.sb.TeleportEffect(lane.edge, lane.index, pos, onward=onward),
        )

    def event_position(self, position: Any, scope: Scope, what: str) -> tuple[Any, float]:
        """A fixed position of an event's action (a relative one would need its entity's place then)."""
        if position is not None and len(position) == 1 and position[0].tag.startswith("Relative"):
            self.problems.add(position[0], "a relative position here (its entity's place is known only at run time)")
            return None, 0.0
        return self.position(position, scope, what)

    def read_routing(self, routing: Any, scope: Scope, name: str) -> Action | None:
        """AssignRouteAction: through its waypoints' edges in order; AcquirePositionAction: through
        the position's edge. After that the entity keeps straight on as one without a route does (a
        SUMO trip ends at its route's end, so the route goes on past the last waypoint)."""
        here = where(self.path, routing)
        lanes: list[Any] = []
        if routing.tag == "AssignRouteAction":
            route = routing.find("Route")
            if route is None:
                self.problems.add(routing, "a CatalogReference route")
                return None
            for waypoint in route.iterfind("Waypoint"):
                lane, _ = self.event_position(waypoint.find("Position"), scope, where(self.path, waypoint))
                if lane is None:
                    return None
                lanes.append(lane)
            if len(lanes) < 1:
                raise ScenarioError(f"{here}: a Route needs at least one Waypoint")
        elif routing.tag == "AcquirePositionAction":
            lane, _ = self.event_position(routing.find("Position"), scope, here)
            if lane is None:
                return None
            lanes.append(lane)
        else:
            self.problems.add(routing)
            return None
        target, via, edges = self.through(lanes)
        kind = "AcquirePosition" if routing.tag == "AcquirePositionAction" else "AssignRoute"
        return Action(
            name,
            False,
            f"RouteEffect({kind}: via {', '.join(edges)}, on to {target})",
            lambda b: b.sb.RouteEffect(target, via=via, keep=True),
        )

    def read_traffic_signal_action(self, action: Any, scope: Scope, name: str) -> Action | None:
        """TrafficSignalStateAction: the light (or its links) shows the state from then on, until a
        later action sets it (SUMO's programme of that light stops: a kept TrafficLightEffect).
        TrafficSignalControllerAction: the SUMO light's programme switches to the phase (its full
        duration, then on as programmed), ending any state an action set."""
        controller = action.find("TrafficSignalControllerAction")
        if controller is not None and len(action) == 1:
            here = where(self.path, controller)
            tls = self.text(controller, "trafficSignalControllerRef", scope)
            phase = phase_index(self.network, tls, self.text(controller, "phase", scope), here)
            return Action(
                name,
                True,
                f"TrafficLightPhaseEffect({tls} phase {phase})",
                lambda b: b.sb.TrafficLightPhaseEffect(tls, phase),
            )
        state_action = action.find("TrafficSignalStateAction")
        if state_action is None or len(action) != 1:
            self.problems.add(action)
            return None
        here = where(self.path, state_action)
        tls, links = signal_links(self.network, self.text(state_action, "name", scope), here)
        state = signal_state(self.network, tls, links, self.text(state_action, "state", scope), here)
        at = f" link{'s' if len(links) > 1 else ''} {','.join(map(str, links))}" if links else ""
        return Action(
            name,
            True,
            f"TrafficLightEffect({tls}{at} '{state}', kept)",
            lambda b: b.sb.TrafficLightEffect(tls, state, links=links, keep=True),
        )
