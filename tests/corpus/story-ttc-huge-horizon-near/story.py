import storyboard as sb


def createStories(board):
    board.registerStory(sb.Story(sb.TtcCondition(1e300, 10), [sb.SignalEffect("x")], name="ttc"))
