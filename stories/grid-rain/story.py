"""Heavy rain over one district of the 6 x 6 grid (stories/grid-rain).

From 120 s to 420 s a downpour covers the 3 x 3 junctions at x, y in {400, 600, 800}: every
vehicle in that district is capped at 5 m/s. A second story warns the drivers that reach the
district still faster than 8 m/s, to show conditions composing with the same area.

Study parameters (``--param``): ``rain_speed`` (m/s, default 5) and ``warn_above`` (m/s, default 8);
``stories/grid-rain/study.toml`` sweeps the first.
"""

from __future__ import annotations

import storyboard
from storyboard import (
    PolygonCondition,
    SignalEffect,
    SpeedConditionGreater,
    SpeedEffect,
    Story,
    TimeCondition,
)

# The district in SUMO coordinates (the net spans 0..1000 m on both axes). The 10 m margin
# keeps the junctions at 400 and 800 inside, so the cap holds across them.
DISTRICT: list[tuple[float, float]] = [(390.0, 390.0), (810.0, 390.0), (810.0, 810.0), (390.0, 810.0)]
RAIN_BEGIN_S = 120.0
RAIN_END_S = 420.0
RAIN_SPEED_MPS = 5.0  # 18 km/h: walking pace for cars in a downpour
WARN_ABOVE_MPS = 8.0


def createStories(board: storyboard.Storyboard) -> None:
    # One shared condition object for both stories: its area and window are defined once.
    rain_speed = float(board.parameter("rain_speed", RAIN_SPEED_MPS))  # type: ignore[arg-type]
    warn_above = float(board.parameter("warn_above", WARN_ABOVE_MPS))  # type: ignore[arg-type]
    raining_here = storyboard.all_of(PolygonCondition(DISTRICT), TimeCondition(RAIN_BEGIN_S, RAIN_END_S))

    board.registerStory(Story(raining_here, [SpeedEffect(rain_speed)], name="rain"))

    # Vehicles entering the district still fast (the cap makes them brake over the next steps).
    too_fast = storyboard.all_of(raining_here, SpeedConditionGreater(warn_above))
    board.registerStory(Story(too_fast, [SignalEffect("heavy rain: slow down")], name="rain-warning"))
