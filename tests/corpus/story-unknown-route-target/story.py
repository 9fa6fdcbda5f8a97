import storyboard as sb


def createStories(board):
    board.registerStory(sb.Story(sb.TimeCondition(2), [sb.RouteEffect('nope_edge')], name='typo'))
