import storyboard as sb


def createStories(board):
    c = sb.TimeCondition(1)
    for _ in range(60):
        c = sb.AndCondition(c, c)
    board.registerStory(sb.Story(c, [sb.SignalEffect("x")], name="deep"))
