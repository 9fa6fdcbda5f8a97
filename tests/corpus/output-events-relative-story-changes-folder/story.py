import os
import storyboard


def createStories(board):
    os.chdir("elsewhere")
    board.registerStory(storyboard.Story(storyboard.TimeCondition(1), [storyboard.SignalEffect("x")], name="a"))
