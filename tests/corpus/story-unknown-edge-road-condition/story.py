import storyboard as sb


def createStories(board):
    board.registerStory(sb.Story(sb.RoadCondition('nope_edge'), [sb.SpeedEffect(5.0)], name='typo'))
