"""A truck breaks down and a roadside unit warns of it, in Python (stories/python-warning).

At 300 s a truck appears standing on the right lane at x = 1500 m (a world story adds it, a story holds
it). The storyboard signals "hazard" to it once; everything V2X is Python (warning.py): the roadside
unit at x = 1200 m hears the signal, and from then on broadcasts where the hazard is; equipped vehicles
that hear it slow down and leave the blocked lane, and record how far ahead of the hazard they were
warned.
"""

from __future__ import annotations

import storyboard
from storyboard import CarSetCondition, SignalEffect, SpawnEffect, StopEffect, Story, TimeCondition, WorldStory

TRUCK = "broken-truck"
BREAKDOWN_S = 300.0
POSITION_M = 1500.0


def createStories(board: storyboard.Storyboard) -> None:
    spawn = SpawnEffect(TRUCK, route=["motorway"], type="truck", lane=0, position=POSITION_M, speed=0)
    board.registerStory(WorldStory(TimeCondition(BREAKDOWN_S), [spawn], name="breakdown"))
    board.registerStory(Story(CarSetCondition([TRUCK]), [StopEffect(), SignalEffect("hazard")], name="truck-stands"))
