import storyboard as sb


def createStories(board):
    board.registerStory(sb.WorldStory(sb.TimeCondition(2), [sb.TrafficLightEffect('nope_tls', 'rrrr')], name='typo'))
