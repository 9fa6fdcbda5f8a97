import storyboard as sb


def createStories(board):
    board.registerStory(sb.WorldStory(sb.TimeCondition(5, 20), [sb.CloseRoadEffect(["B1C1"])], name="closure"))
