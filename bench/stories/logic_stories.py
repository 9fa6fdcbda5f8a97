"""The story-logic benchmark set: Hold, Not, Headway and Distance, one story each, over every vehicle.

It sits beside the six-story set (six_stories.py) so that bench/storyboard.py can print what the
newer conditions cost per vehicle-step. Coordinates are Artery canvas coordinates, as there, so
the same script fits every bench grid.
"""

import storyboard
from six_stories import square  # the same districts (the script's folder is on sys.path)
from storyboard import (
    AndCondition,
    Coord,
    DistanceCondition,
    HeadwayCondition,
    HoldCondition,
    NotCondition,
    SignalEffect,
    SpeedConditionLess,
    SpeedFactorEffect,
    Story,
    TimeCondition,
)


def createStories(board: storyboard.Storyboard) -> None:
    # 1. Hold: slow for 10 s in a row (per-vehicle state every step).
    board.registerStory(Story(HoldCondition(SpeedConditionLess(2.0), 10), [SignalEffect("stuck")], name="hold"))
    # 2. Not: outside the top-left district after 50 s, drivers keep 90 % of the limit.
    board.registerStory(
        Story(
            AndCondition(TimeCondition(50), NotCondition(square(0, 0, 1200))),
            [SpeedFactorEffect(0.9)],
            name="not",
        )
    )
    # 3. Headway: under 1 s behind the leader (libsumo getLeader for every vehicle, every step).
    board.registerStory(Story(HeadwayCondition(1.0), [SignalEffect("tailgating")], name="headway"))
    # 4. Distance: within 300 m of a point, and within 100 m of a named vehicle (--param target=ID;
    #    the grids' ids are zero-padded to their vehicle count's width).
    target = str(board.parameter("target", "veh0010"))
    board.registerStory(
        Story(DistanceCondition(Coord(600, 600), 300.0), [SignalEffect("near centre")], name="distance point")
    )
    board.registerStory(Story(DistanceCondition(target, 100.0), [SignalEffect("near target")], name="distance vehicle"))
