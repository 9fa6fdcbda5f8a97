import time
def createStories(board):
    time.sleep(60)
