import storyboard as sb


def createStories(board):
    board.registerStory(sb.Story(sb.TimeCondition(2), [sb.SignalEffect("x")], name="big", max_activations=-2**70))
