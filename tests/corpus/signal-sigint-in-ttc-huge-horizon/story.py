import time
from pathlib import Path

import storyboard as sb


class Paced(sb.Condition):
    """Makes each step last at least 50 ms whatever the machine, so the run (300 steps, --end 300)
    is still stepping, TTC and all, when the signal sent at the marker arrives."""

    columns = ("speed",)

    def test_all(self, snapshot):
        Path("stepping").touch()
        time.sleep(0.05)
        return snapshot.speeds < 0


def createStories(board):
    board.registerStory(sb.Story(sb.TtcCondition(1e308, 1e308), [sb.SignalEffect("x")], name="ttc"))
    board.registerStory(sb.Story(Paced(), [], name="paced"))
