"""The first N vehicles entering an area (stories/first-n).

A traffic survey in the middle of the street between junctions B1 (200, 200) and C1 (400, 200)
of a 4 x 4 grid: the first 5 vehicles that enter the 40 m survey zone, in either direction, are
slowed to 3 m/s while they drive through it; every later vehicle passes at normal speed. A second
story signals every entry into the zone, to compare.
"""

from __future__ import annotations

import storyboard
from storyboard import LimitCondition, PolygonCondition, SignalEffect, SpeedEffect, Story

N = 5
SURVEY_SPEED_MPS = 3.0

# The zone in SUMO coordinates: x 280..320 m, across all four lanes of B1-C1 (y 195.2..204.8).
# Mid-street, so no trip departs inside it (trips depart at the start of an edge): every
# vehicle in it has entered it.
ZONE_SUMO: list[tuple[float, float]] = [(280.0, 190.0), (320.0, 190.0), (320.0, 210.0), (280.0, 210.0)]


def createStories(board: storyboard.Storyboard) -> None:
    # Artery style: canvas Coords from SUMO positions (PolygonCondition takes either).
    zone_points = [board.convertTraciPosition(x, y) for x, y in ZONE_SUMO]

    # all_of tests left to right and stops at the first false: LimitCondition only sees vehicles
    # already in the zone, so it admits the first N entering it. Swapped, it would admit the
    # first N vehicles it tests anywhere in the net (here none of them ever passes the zone).
    # An admitted vehicle stays admitted (the cap applies again should it re-enter); the count
    # never goes back, so later vehicles are never admitted.
    zone = PolygonCondition(zone_points)
    first_n = storyboard.all_of(zone, LimitCondition(N))
    board.registerStory(
        Story(first_n, [SpeedEffect(SURVEY_SPEED_MPS), SignalEffect("selected for survey")], name="survey")
    )

    # Every entry into the zone, for comparison with the N surveyed ones.
    board.registerStory(Story(zone, [SignalEffect("entered zone")], name="zone-entry"))
