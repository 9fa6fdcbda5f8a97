import storyboard


class Record(storyboard.Effect):
    def apply(self, vehicle):
        board.record(b"speed\xff\xfe", 1.0)

    def remove(self, vehicle):
        pass


def createStories(b):
    global board
    board = b
    board.registerStory(storyboard.Story(storyboard.TimeCondition(1), [Record()]))
