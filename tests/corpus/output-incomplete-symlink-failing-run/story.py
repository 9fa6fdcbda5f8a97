def createStories(board):
    raise RuntimeError("boom")
