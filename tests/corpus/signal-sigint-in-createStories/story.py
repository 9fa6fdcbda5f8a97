import time
from pathlib import Path


def createStories(board):
    Path("stepping").touch()  # the test's cue: the signal comes now, inside the sleep
    time.sleep(60)
