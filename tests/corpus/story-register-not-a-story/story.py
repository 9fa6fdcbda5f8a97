def createStories(board):
    board.registerStory(42)
