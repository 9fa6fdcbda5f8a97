"""The six-story benchmark set: one story per kind of work the storyboard does each step.

Coordinates are Artery canvas coordinates (origin top-left of the network), so the same script
fits every bench grid: the districts are the top-left 1.2 km square and a 400 m square.
"""

import storyboard
from storyboard import (
    AndCondition,
    CarSetCondition,
    Coord,
    LimitCondition,
    PolygonCondition,
    SignalEffect,
    SpeedConditionGreater,
    SpeedDifferenceConditionSlower,
    SpeedEffect,
    StopEffect,
    Story,
    TimeCondition,
    TtcCondition,
)


def square(x: float, y: float, size: float) -> PolygonCondition:
    return PolygonCondition([Coord(x, y), Coord(x + size, y), Coord(x + size, y + size), Coord(x, y + size)])


def createStories(board: storyboard.Storyboard) -> None:
    # 1. Rain over a district: polygon + time -> speed cap.
    board.registerStory(Story(AndCondition(TimeCondition(50), square(0, 0, 1200)), [SpeedEffect(8.0)], name="rain"))
    # 2. Time-to-collision warning among neighbours.
    board.registerStory(Story(TtcCondition(2.0, 50.0), [SignalEffect("ttc warning")], name="ttc"))
    # 3. A much slower neighbour nearby.
    board.registerStory(
        Story(
            SpeedDifferenceConditionSlower(8.0, 30.0),
            [SignalEffect("slow vehicle ahead")],
            name="speed difference",
        )
    )
    # 4. The first 20 vehicles entering an area are stopped for a minute.
    board.registerStory(
        Story(
            AndCondition(TimeCondition(60, 120), AndCondition(square(800, 800, 400), LimitCondition(20))),
            [StopEffect()],
            name="first 20",
        )
    )
    # 5. Two named cars break down.
    board.registerStory(
        Story(
            AndCondition(CarSetCondition({"veh0010", "veh0020"}), TimeCondition(80, 140)),
            [StopEffect()],
            name="breakdown",
        )
    )
    # 6. Speeding.
    board.registerStory(Story(SpeedConditionGreater(13.0), [SignalEffect("speeding")], name="speeding"))
