"""A breakdown on a straight one-lane road (stories/breakdown).

The vehicle "broken" develops engine trouble at 50 s (near x = 570 m) and limps on at 3 m/s; at
80 s it dies and stands until 140 s, when it is repaired and drives on. The traffic behind it,
which cannot overtake on one lane, gets warned about the slow vehicle ahead.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
import storyboard
from storyboard import (
    CarSetCondition,
    SignalEffect,
    SpeedDifferenceConditionFaster,
    SpeedDifferenceConditionSlower,
    SpeedEffect,
    StopEffect,
    Story,
    TimeCondition,
)

BROKEN = "broken"
TROUBLE_BEGIN_S = 50.0
DEAD_BEGIN_S = 80.0
REPAIRED_S = 140.0
LIMP_SPEED_MPS = 3.0

# Closing in on something more than 8 m/s slower within 150 m: at 80 km/h that is a vehicle a
# driver has to brake hard for.
DELTA_MPS = 8.0
RANGE_M = 150.0


class BehindOf(storyboard.Condition):
    """The vehicles upstream of `vehicle_id` on this road (it runs towards +x); none while that
    vehicle is not on the road. Vectorised: one numpy comparison per step."""

    def __init__(self, vehicle_id: str) -> None:
        super().__init__()
        self.vehicle_id = vehicle_id

    def test_all(self, snapshot: storyboard.Snapshot) -> npt.NDArray[np.bool_]:
        xs = np.asarray(snapshot.positions)[:, 0]
        index = snapshot.index_of(self.vehicle_id)
        if index is None:
            return np.zeros(len(xs), dtype=bool)
        return xs < xs[index]


def createStories(board: storyboard.Storyboard) -> None:
    broken = CarSetCondition(BROKEN)

    # Two overlapping stories on one vehicle: from 80 s the stop holds it, although the speed cap
    # is still active; both end at 140 s and the vehicle gets its own speed back.
    limping = storyboard.all_of(broken, TimeCondition(TROUBLE_BEGIN_S, REPAIRED_S))
    board.registerStory(Story(limping, [SpeedEffect(LIMP_SPEED_MPS)], name="engine-trouble"))
    dead = storyboard.all_of(broken, TimeCondition(DEAD_BEGIN_S, REPAIRED_S))
    board.registerStory(Story(dead, [StopEffect()], name="breakdown"))

    # Vehicles behind the broken one, much faster than a neighbour (the broken vehicle or the queue
    # behind it); "others" names the slow ones. The distance test looks both ways: BehindOf keeps
    # out the vehicles that had passed the spot, and the window the queue's own dissolution after
    # the repair (its head pulling away from the vehicles still standing behind it).
    approaching = storyboard.all_of(
        TimeCondition(TROUBLE_BEGIN_S, REPAIRED_S),
        BehindOf(BROKEN),
        SpeedDifferenceConditionFaster(DELTA_MPS, RANGE_M),
    )
    board.registerStory(Story(approaching, [SignalEffect("slow vehicle ahead")], name="slow-vehicle-warning"))

    # The broken vehicle's own view: traffic around it much faster (mostly coming up from behind),
    # so it switches its hazard lights on.
    hazard = storyboard.all_of(broken, SpeedDifferenceConditionSlower(DELTA_MPS, RANGE_M))
    board.registerStory(Story(hazard, [SignalEffect("hazard lights")], name="hazard-lights"))
