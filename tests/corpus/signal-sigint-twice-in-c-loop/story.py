
import storyboard
def createStories(board):
    sum(range(10**12))
