import storyboard as sb


def createStories(board):
    board.registerStory(sb.WorldStory(sb.TimeCondition(2), [sb.CloseRoadEffect('nope_edge')], name='typo'))
