import storyboard as sb


def createStories(board):
    board.registerStory(sb.WorldStory(sb.TimeCondition(10, 100), [sb.CloseRoadEffect(["west_in"])], name="closure"))
