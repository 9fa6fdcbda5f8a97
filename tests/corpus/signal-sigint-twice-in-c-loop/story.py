from pathlib import Path


def createStories(board):
    Path("stepping").touch()  # the test's cue: the signals come now, inside the C loop
    sum(range(10**12))
