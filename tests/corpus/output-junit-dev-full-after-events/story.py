import storyboard
def createStories(board):
    board.registerStory(storyboard.Story(storyboard.TimeCondition(1), [storyboard.SignalEffect("x")]))
