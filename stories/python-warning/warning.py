"""The python-warning scenario's V2X logic (see README.md): a roadside unit's hazard warning and the
vehicles' reaction, as services written in Python (storyboard.services)."""

from __future__ import annotations

from storyboard.services import Message, Service, Signal


class HazardWarner(Service):
    """On the roadside unit: learns the hazard from the storyboard's signal and broadcasts it every `interval` s."""

    attributes = {"interval": float}

    def initialize(self) -> None:
        self.interval = self.attribute("interval", 0.5)
        self.hazard: tuple[float, float, int] | None = None
        self.since = 0.0  # when the unit learned of it
        self.sent = 0
        self.listen_to_all_signals()  # the signal is the truck's, not the unit's

    def receive_signal(self, signal: Signal) -> None:
        if signal.cause != "hazard" or signal.on_exit or self.hazard is not None:
            return
        snapshot = self.snapshot
        row = snapshot.index_of(signal.ego)
        if row is None:
            return
        x, y = snapshot.positions[row]
        self.hazard = (float(x), float(y), 0)  # the truck stands on the right lane
        self.since = self.time
        self.announce()

    def announce(self) -> None:
        assert self.hazard is not None
        x, y, lane = self.hazard
        self.send("HazardWarning", 96, {"x": x, "y": y, "lane": lane, "since": self.since})
        self.sent += 1
        self.schedule_after(self.interval, self.announce)

    def finish(self) -> None:
        self.record_scalar("warnings_sent", self.sent)


class HazardReaction(Service):
    """On vehicles: warned ahead of the hazard, slow to `speed` m/s and leave its lane; record the distance."""

    attributes = {"speed": float}

    def initialize(self) -> None:
        self.speed_limit = self.attribute("speed", 20.0)
        self.warned = False

    def indicate(self, message: Message) -> None:
        if self.warned or message.type != "HazardWarning":
            return
        hazard = message.payload
        distance = self.driving_distance(hazard["x"], hazard["y"])
        if distance is None or distance <= 0:
            return  # passed it already
        self.warned = True
        self.record_scalar("warning_distance", distance)
        self.record_scalar("warning_delay", self.time - hazard["since"])
        self.set_max_speed(self.speed_limit)
        self.set_color(255, 160, 0)
        if self.lane_index == hazard["lane"]:
            self.change_lane(hazard["lane"] + 1, 60.0)

    def trigger(self) -> None:
        # Past the hazard: back to the vehicle's own speed and colour.
        if self.warned and self.position[0] > 1550.0:
            self.end_max_speed()
            self.end_color()
