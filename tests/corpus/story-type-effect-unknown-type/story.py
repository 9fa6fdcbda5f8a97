import storyboard as sb


def createStories(board):
    board.registerStory(sb.Story(sb.TimeCondition(2), [sb.TypeEffect("nosuchtype")], name="typer"))
