import storyboard as sb


def createStories(board):
    board.registerStory(sb.WorldStory(sb.TimeCondition(5, 70), [sb.CloseRoadEffect(["A0A1"])], name="closure"))
