import storyboard as sb


def createStories(board):
    board.registerStory(sb.WorldStory(sb.TimeCondition(5, 60), [sb.CloseRoadEffect(["B1C1"])], name="closure"))
    board.registerStory(sb.WorldStory(sb.TimeCondition(10), [sb.SpawnEffect("s", route=["A1B1", "B1C1", "C1D1"])], name="spawner"))
