"""A police car switches its siren on (stories/highway-police).

From 10 s on, the storyboard signals "siren on" to police0's services (once, when the story
activates). Its PoliceService then broadcasts ClearLane messages with its road and lane, and the
ClearLaneService of every vehicle around it on the same road but in another lane slows to 25 m/s.
"""

from __future__ import annotations

import storyboard
from storyboard import AndCondition, CarSetCondition, SignalEffect, Story, TimeCondition


def createStories(board: storyboard.Storyboard) -> None:
    siren = AndCondition(TimeCondition(10), CarSetCondition("police0"))
    board.registerStory(Story(siren, [SignalEffect("siren on")], name="siren"))
