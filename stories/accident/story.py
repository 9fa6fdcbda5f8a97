"""An accident on a straight two-lane road (stories/accident).

At 60 s the vehicle "crasher" (then near x = 1070 m) stops dead in its lane and stays there until
180 s. Vehicles closing in on the wreck, or on the queue behind it, get a collision warning.
"""

from __future__ import annotations

import storyboard
from storyboard import (
    CarSetCondition,
    PolygonCondition,
    SignalEffect,
    StopEffect,
    Story,
    TimeCondition,
    TtcCondition,
)

CRASHER = "crasher"
CRASH_BEGIN_S = 60.0
CRASH_END_S = 180.0

# The stretch around the accident, both lanes (the road runs along y = 0, lanes at y = -4.8 and
# -1.6), in SUMO coordinates. Far enough upstream that drivers at 100 km/h are still approaching.
ACCIDENT_ZONE: list[tuple[float, float]] = [(700.0, -8.0), (1300.0, -8.0), (1300.0, 2.0), (700.0, 2.0)]

# A warning when the footprints, moving on at their current speeds, would touch within 4 s:
# SUMO drivers start braking for a stopped car about 3 s (100 m) before it at 100 km/h.
TTC_S = 4.0
TTC_RANGE_M = 120.0


def createStories(board: storyboard.Storyboard) -> None:
    crash = storyboard.all_of(CarSetCondition(CRASHER), TimeCondition(CRASH_BEGIN_S, CRASH_END_S))
    board.registerStory(Story(crash, [StopEffect()], name="crash"))

    # The zone keeps ordinary close following elsewhere on the road from raising warnings, the
    # window limits them to the accident; the TTC result names the vehicles in conflict ("others").
    warning = storyboard.all_of(
        TimeCondition(CRASH_BEGIN_S, CRASH_END_S),
        PolygonCondition(ACCIDENT_ZONE),
        TtcCondition(TTC_S, TTC_RANGE_M),
    )
    board.registerStory(Story(warning, [SignalEffect("collision warning")], name="collision-warning"))
