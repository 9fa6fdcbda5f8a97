from pathlib import Path

import storyboard


class C(storyboard.Condition):
    def test(self, vehicle):
        Path("stepping").touch()  # the test's cue: the signal comes now, inside the busy loop
        while True:
            pass


def createStories(board):
    board.registerStory(storyboard.Story(C(), []))
