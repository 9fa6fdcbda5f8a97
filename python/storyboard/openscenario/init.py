"""The storyboard's Init: where each entity starts, its speed and its route (assigned, or to a
position it acquires)."""

from __future__ import annotations

from typing import Any

from .errors import where
from .model import Start
from .parameters import Scope
from .reader import Reader


class InitReader(Reader):
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
        elif action.tag == "RoutingAction" and action.find("AcquirePositionAction") is not None:
            # Routed there once it is on the road (from where it is), then straight on.
            lane, _ = self.position(action.find("AcquirePositionAction/Position"), scope, what)
            if lane is not None:
                target, via, _ = self.through([lane])
                start.acquire = (target, via)
        else:
            self.problems.add(action)
