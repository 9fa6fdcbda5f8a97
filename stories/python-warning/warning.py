"""The V2X logic of stories/python-warning, all in Python (storyboard.services).

HazardBeacon runs on the roadside unit: it listens to the stories' signals, learns where the
hazard is from the car that signals it, and broadcasts a HazardWarning every `interval` seconds
until the hazard is cleared. WarnedDriver runs on every equipped vehicle: the first warning about a
hazard ahead of it caps its speed at `slow` m/s and, with `keepClear`, moves it out of the hazard's
lane; it passes the warning on once (up to `hops` hops from the unit), so the more vehicles are
equipped the further upstream a warning travels. Each vehicle records how far ahead the hazard was
when it was first warned (`warning_distance`, m) and how many hops the warning took (`warning_hops`).
"""

from __future__ import annotations

from typing import ClassVar

from storyboard.services import Message, Service, Signal

WARNING = "HazardWarning"
WARNING_BYTES = 100  # header, position, time and hop count: a small DENM's size
LANE_WIDTH = 3.2  # SUMO's default lane width: a vehicle this close (laterally) is in the hazard's lane


class HazardBeacon(Service):
    attributes: ClassVar = {"interval": float}

    def initialize(self) -> None:
        self.listen_to_all_signals()  # the hazard's signal goes to the crashed car, not to the unit
        self.hazard: tuple[float, float] | None = None
        self.timer: int | None = None

    def receive_signal(self, signal: Signal) -> None:
        if signal.cause == "hazard":
            index = self.snapshot.index_of(signal.ego)
            if index is None:
                return
            x, y = self.snapshot.positions[index]
            self.hazard = (float(x), float(y))
            self.broadcast()
        elif signal.cause == "hazard cleared" and self.timer is not None:
            self.cancel(self.timer)
            self.hazard = self.timer = None

    def broadcast(self) -> None:
        assert self.hazard is not None
        x, y = self.hazard
        self.send(WARNING, WARNING_BYTES, {"x": x, "y": y, "hops": 1})
        self.timer = self.schedule_after(self.attribute("interval", 0.5), self.broadcast)


class WarnedDriver(Service):
    attributes: ClassVar = {"slow": float, "keepClear": bool, "hops": int}

    def initialize(self) -> None:
        self.hazard: tuple[float, float] | None = None  # while it acts on a warning

    def indicate(self, message: Message) -> None:
        if message.type != WARNING or self.hazard is not None:
            return
        warning = message.payload
        ahead = self.driving_distance(warning["x"], warning["y"])
        if ahead is None or ahead <= 0:
            return  # behind it, or not on its route
        self.hazard = (warning["x"], warning["y"])
        self.record_scalar("warning_distance", ahead)
        self.record_scalar("warning_hops", warning["hops"])
        self.set_max_speed(self.attribute("slow", 20.0))
        if self.attribute("keepClear", True) and abs(self.position[1] - warning["y"]) < LANE_WIDTH / 2:
            self.change_lane_relative(1 if self.lane_index == 0 else -1, 10.0)
        if warning["hops"] < self.attribute("hops", 3):
            self.send(WARNING, WARNING_BYTES, {**warning, "hops": warning["hops"] + 1})

    def trigger(self) -> None:
        if self.hazard is None:
            return
        ahead = self.driving_distance(*self.hazard)
        if ahead is None or ahead < 0:  # past it: back to its own speed
            self.end_max_speed()
            self.hazard = None
