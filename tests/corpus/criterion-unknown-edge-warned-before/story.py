import storyboard as sb


def createStories(board):
    board.registerStory(sb.Story(sb.TimeCondition(2), [sb.SignalEffect("x")], name="s"))
    board.registerCriterion(sb.WarnedBefore("nope_edge"), name="warned")
