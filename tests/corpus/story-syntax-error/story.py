def createStories(board)
    pass
