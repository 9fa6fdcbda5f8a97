def f(n):
    return f(n + 1)
def createStories(board):
    f(0)
