"""An accident on a motorway, and the vehicles its DENM warns (stories/motorway-accident).

The car "crash" stops dead from 40 s on (the accident) and its story signals "accident" to its
services; its DEN service's StoryboardEvent use case (den-use-cases.xml) then broadcasts a DENM
(cause 2, accident) to a 1,000 m circle around it every second. Every vehicle that received it
(its DENM memory holds the event) drives at most 15 m/s: the second story, which reacts to V2X.
At 160 s the accident is cleared: the crash car drives on, its exit signal "accident over" ends
the event, the receivers drop it and the warned vehicles speed up again.
"""

from __future__ import annotations

import storyboard
from storyboard import (
    AndCondition,
    CarSetCondition,
    DenmCondition,
    SignalEffect,
    SpeedEffect,
    StopEffect,
    Story,
    TimeCondition,
)

ACCIDENT_CAUSE = 2  # EN 302 637-3 cause code "accident"


def createStories(board: storyboard.Storyboard) -> None:
    accident = AndCondition(CarSetCondition("crash"), TimeCondition(40, 160))
    board.registerStory(Story(accident, [StopEffect(), SignalEffect("accident", "accident over")], name="accident"))
    warned = DenmCondition(cause=ACCIDENT_CAUSE)
    board.registerStory(Story(warned, [SpeedEffect(15.0)], name="warned"))
