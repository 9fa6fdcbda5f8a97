import storyboard as sb


def createStories(board):
    board.registerStory(sb.WorldStory(sb.TimeCondition(5, 70), [sb.CloseRoadEffect(["D3D2"])], name="closure"))
