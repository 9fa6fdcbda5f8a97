import storyboard
def createStories(board):
    board.registerStory(storyboard.Story(storyboard.TimeCondition('soon'), []))
