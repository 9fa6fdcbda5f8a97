import storyboard as sb


def createStories(board):
    board.registerStory(sb.WorldStory(sb.TimeCondition(2), [sb.SpawnEffect("s", from_edge=":A1_0", to_edge="A0A1")], name="spawner"))
