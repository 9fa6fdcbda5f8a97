"""A hazard on a motorway, told to the roadside unit by a story signal (stories/python-warning).

The car "crash" stops dead from 40 s to 160 s and signals "hazard" (and "hazard cleared" when the
story ends). The V2X side is all Python (warning.py): the roadside unit hears the signal, learns
where the hazard is and broadcasts warnings; warned vehicles slow down and leave the hazard's lane.
"""

from __future__ import annotations

import storyboard
from storyboard import AndCondition, CarSetCondition, SignalEffect, StopEffect, Story, TimeCondition


def createStories(board: storyboard.Storyboard) -> None:
    hazard = AndCondition(CarSetCondition("crash"), TimeCondition(40, 160))
    board.registerStory(Story(hazard, [StopEffect(), SignalEffect("hazard", "hazard cleared")], name="hazard"))
