"""The soak set (bench/soak.py): stories that stack and remove effects all the time.

On the `soak` grid (12 x 12 junctions, 0..2200 m, SUMO frame) vehicles cross overlapping districts
with different caps, are stopped for a few seconds in short windows, draw random decisions
(Likelihood, Deferring) and signal services that exchange V2X messages. One story holds a cap on
every vehicle, so the board keeps state for each running vehicle: at the end that count must
equal the running vehicles (nothing kept for vehicles that left).

`--param rss_log=FILE` makes a probe write the process's resident memory every simulated
`rss_every` seconds (default 300).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import numpy.typing as npt
import storyboard
from storyboard import (
    AndCondition,
    AnyCondition,
    DeferringCondition,
    LikelihoodCondition,
    PolygonCondition,
    SignalEffect,
    SpeedConditionGreater,
    SpeedEffect,
    StopEffect,
    Story,
    TimeCondition,
)


def area(x0: float, y0: float, x1: float, y1: float) -> PolygonCondition:
    return PolygonCondition([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])


def resident_kb() -> int:
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    return -1


class RssProbe(storyboard.Condition):
    """Appends "time rss_kb running" to a file every `every` simulated seconds; never true."""

    def __init__(self, path: str, every: float) -> None:
        super().__init__()
        self._out = open(path, "w", encoding="utf-8")  # noqa: SIM115 - open for the whole run
        self._every = every
        self._next = 0.0

    def test_all(self, snapshot: storyboard.Snapshot) -> npt.NDArray[np.bool_]:
        if snapshot.time >= self._next:
            self._out.write(f"{snapshot.time:.0f} {resident_kb()} {len(snapshot)}\n")
            self._out.flush()
            self._next += self._every
        return np.zeros(len(snapshot), dtype=bool)


def createStories(board: storyboard.Storyboard) -> None:
    rng = board.random_generator(0)
    # A cap above every speed reached: the board keeps a stack for every vehicle.
    board.registerStory(Story(SpeedConditionGreater(-1.0), [SpeedEffect(45.0)], name="everyone"))
    # Two overlapping districts: vehicles enter them from either side, so caps stack in both orders.
    board.registerStory(Story(area(0, 0, 1200, 2200), [SpeedEffect(9.0)], name="rain west"))
    board.registerStory(Story(area(600, 600, 1600, 1600), [SpeedEffect(7.0)], name="rain centre"))
    board.registerStory(
        Story(AndCondition(area(1000, 0, 2200, 1000), LikelihoodCondition(rng, 0.5)), [SpeedEffect(5.0)], name="fog")
    )
    # Short stops: 15 s windows every 2 minutes, in a block, after a random delay per vehicle.
    windows = AnyCondition(*[TimeCondition(t, t + 15) for t in range(60, 3600, 120)])
    board.registerStory(
        Story(
            AndCondition(windows, AndCondition(area(800, 800, 1400, 1400), DeferringCondition(rng, 2, 10))),
            [StopEffect()],
            name="stops",
        )
    )
    # Sirens (the PoliceService of vehicles whose id ends in 77 broadcasts ClearLane messages).
    board.registerStory(Story(DeferringCondition(rng, 30, 120), [SignalEffect("siren on")], name="siren"))
    board.registerStory(Story(SpeedConditionGreater(12.5), [SignalEffect("speeding")], name="speeding"))
    rss_log = board.parameter("rss_log", "")
    if rss_log:
        every = float(board.parameter("rss_every", 300.0))  # type: ignore[arg-type]
        board.registerStory(Story(RssProbe(str(rss_log), every), [], name="rss probe"))
