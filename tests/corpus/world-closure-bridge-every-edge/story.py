import storyboard as sb


def createStories(board):
    board.registerStory(sb.WorldStory(sb.TimeCondition(10, 100), [sb.CloseRoadEffect(["bridge_e", "bridge_w", "east_in", "east_out", "ebank_n", "ebank_s", "south_e", "south_w", "wbank_n", "wbank_s", "west_in", "west_out"])], name="closure"))
