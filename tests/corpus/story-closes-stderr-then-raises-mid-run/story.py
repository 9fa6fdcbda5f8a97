import os

import storyboard


class Closing(storyboard.Condition):
    def test(self, vehicle):
        os.close(2)
        raise ValueError("after closing stderr")


def createStories(board):
    board.registerStory(storyboard.Story(Closing(), []))
