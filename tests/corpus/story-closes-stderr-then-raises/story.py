import os


def createStories(board):
    os.close(2)
    raise RuntimeError("after closing stderr")
