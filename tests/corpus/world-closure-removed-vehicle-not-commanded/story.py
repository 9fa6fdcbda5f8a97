import storyboard as sb


def createStories(board):
    board.registerStory(sb.WorldStory(sb.TimeCondition(10, 60), [sb.CloseRoadEffect(["east_out"])], name="closure"))
    # Acts on every vehicle in every step, so also on those the closure removes right after SUMO inserted them.
    board.registerStory(sb.Story(sb.TimeCondition(0), [sb.SpeedEffect(5.0)], name="slow"))
