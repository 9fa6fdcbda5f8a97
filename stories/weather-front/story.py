"""A weather front over the 6 x 6 grid (stories/weather-front).

The front is a polygon SUMO loads with the scenario (``<poly id="front">`` in ``front.poly.xml``,
listed in the sumocfg's additional-files, as netedit would save a drawn district): a band about
280 m wide from the north-west corner to the south-east one. The story reads its shape from SUMO
with ``storyboard.sumo_polygon("front")``. The front arrives at 150 s and has passed at 450 s; in
between every vehicle inside it drives at a share of the speed limit (SUMO's speed factor) and is
painted blue for sumo-gui.

Study parameter (``--param``): ``front_factor`` (the speed factor inside the front, default 0.5).
"""

from __future__ import annotations

import storyboard
from storyboard import ColorEffect, PolygonCondition, SpeedFactorEffect, Story, TimeCondition

FRONT_ID = "front"  # the <poly> id in front.poly.xml
FRONT_ARRIVES_S = 150.0
FRONT_PASSES_S = 450.0
FRONT_FACTOR = 0.5  # half the speed limit: 25 km/h on the grid's 50 km/h roads
FRONT_COLOR = (40, 60, 255)


def createStories(board: storyboard.Storyboard) -> None:
    factor = float(board.parameter("front_factor", FRONT_FACTOR))  # type: ignore[arg-type]
    # SUMO has loaded the scenario before the script runs: the polygon comes in SUMO's frame.
    under_front = storyboard.all_of(
        PolygonCondition(storyboard.sumo_polygon(FRONT_ID)), TimeCondition(FRONT_ARRIVES_S, FRONT_PASSES_S)
    )
    board.registerStory(Story(under_front, [SpeedFactorEffect(factor), ColorEffect(FRONT_COLOR)], name="weather-front"))
