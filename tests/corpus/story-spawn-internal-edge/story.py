import storyboard as sb


def createStories(board):
    board.registerStory(sb.WorldStory(sb.TimeCondition(2), [sb.SpawnEffect("s", route=[":A0_0"])], name="spawner"))
