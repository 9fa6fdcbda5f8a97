import storyboard as sb


def createStories(board):
    c = sb.TimeCondition(1)
    for _ in range(5000):
        c = sb.AnyCondition(c)
    board.registerStory(sb.Story(c, [sb.SignalEffect("x")], name="deep"))
