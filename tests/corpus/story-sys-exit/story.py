import sys
def createStories(board):
    sys.exit(3)
