import storyboard
def createStories(board):
    board.registerStory(storyboard.Story(storyboard.LimitCondition(2**64), []))
