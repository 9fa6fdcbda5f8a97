def createStories(board):
    raise ValueError('boom')
