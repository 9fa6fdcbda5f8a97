"""A truck broken down on the motorway (stories/broken-down-truck).

At 300 s a truck appears standing on the right lane (lane 0) at x = 1500 m, added by a world story,
and stays there: a story holds it at speed 0 from its first step. Vehicles closing in behind it
(headway to it under 4 s, within 300 m) get a warning.
"""

from __future__ import annotations

import storyboard
from storyboard import (
    CarSetCondition,
    DistanceCondition,
    HeadwayCondition,
    SignalEffect,
    SpawnEffect,
    StopEffect,
    Story,
    TimeCondition,
    WorldStory,
)

TRUCK = "broken-truck"
BREAKDOWN_S = 300.0
POSITION_M = 1500.0
WARNING_RANGE_M = 300.0
HEADWAY_S = 4.0


def createStories(board: storyboard.Storyboard) -> None:
    spawn = SpawnEffect(TRUCK, route=["motorway"], type="truck", lane=0, position=POSITION_M, speed=0)
    board.registerStory(WorldStory(TimeCondition(BREAKDOWN_S), [spawn], name="breakdown"))
    board.registerStory(Story(CarSetCondition([TRUCK]), [StopEffect()], name="truck-stands"))
    # HeadwayCondition yields the leader, DistanceCondition the truck: their conjunction holds only
    # for vehicles whose leader is the truck.
    closing_in = storyboard.all_of(DistanceCondition(TRUCK, WARNING_RANGE_M), HeadwayCondition(HEADWAY_S))
    board.registerStory(Story(closing_in, [SignalEffect("broken-down truck ahead")], name="warning"))
