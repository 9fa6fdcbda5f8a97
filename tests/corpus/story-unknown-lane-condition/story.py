import storyboard as sb


def createStories(board):
    board.registerStory(sb.Story(sb.LaneCondition('nope_lane_0'), [sb.SpeedEffect(5.0)], name='typo'))
