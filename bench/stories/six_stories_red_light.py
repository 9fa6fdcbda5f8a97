"""The six-story set and a NoRedLightRunning criterion over every vehicle: what a criterion that
looks at every vehicle every step adds (bench/instructions.py --story)."""

import runpy
from pathlib import Path

import storyboard

_six = runpy.run_path(str(Path(__file__).with_name("six_stories.py")))


def createStories(board: storyboard.Storyboard) -> None:
    _six["createStories"](board)
    board.registerCriterion(storyboard.NoRedLightRunning())
