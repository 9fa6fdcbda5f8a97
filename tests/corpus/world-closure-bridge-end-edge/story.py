import storyboard as sb


def createStories(board):
    board.registerStory(sb.WorldStory(sb.TimeCondition(10, 100), [sb.CloseRoadEffect(["east_out"])], name="closure"))
