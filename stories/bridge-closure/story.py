"""The bridge closed for four minutes (stories/bridge-closure).

From 120 s to 360 s the bridge between the towns (edges bridge_e and bridge_w) is closed: nobody
may drive onto it, and traffic takes the southern bridge instead. Vehicles on the detour are told
so (a "detour" signal, once per vehicle), which makes the re-routing visible in the event log.
"""

from __future__ import annotations

import storyboard
from storyboard import CloseRoadEffect, RoadCondition, SignalEffect, Story, TimeCondition, WorldStory

BRIDGE = ["bridge_e", "bridge_w"]
DETOUR = ["south_e", "south_w"]
CLOSED_FROM_S = 120.0
CLOSED_UNTIL_S = 360.0


def createStories(board: storyboard.Storyboard) -> None:
    closed = TimeCondition(CLOSED_FROM_S, CLOSED_UNTIL_S)
    board.registerStory(WorldStory(closed, [CloseRoadEffect(BRIDGE)], name="bridge-closed"))
    # Anyone on the southern bridge is there because of the closure (it is the long way round);
    # the window adds the time the last ones re-routed need to cross it.
    on_detour = storyboard.all_of(TimeCondition(CLOSED_FROM_S, CLOSED_UNTIL_S + 120), RoadCondition(DETOUR))
    board.registerStory(Story(on_detour, [SignalEffect("detour")], name="detour", max_activations=1))
