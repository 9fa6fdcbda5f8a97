import storyboard as sb


def createStories(board):
    board.registerStory(sb.Story(sb.TtcCondition(1e308, 1e308), [sb.SignalEffect("x")], name="ttc"))
