import time
from pathlib import Path

import storyboard


class Slow(storyboard.Condition):
    columns = ("speed",)

    def test_all(self, snapshot):
        Path("stepping").touch()  # the test's cue: the run is stepping
        time.sleep(0.05)  # at least 50 ms a step whatever the machine: the signal comes mid-run
        return snapshot.speeds < 0


def createStories(board):
    board.registerStory(storyboard.Story(Slow(), []))
