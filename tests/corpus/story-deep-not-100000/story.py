import storyboard as sb


def createStories(board):
    c = sb.TimeCondition(1)
    for _ in range(100_000):
        c = sb.NotCondition(c)
    board.registerStory(sb.Story(c, [sb.SignalEffect("x")], name="deep"))
