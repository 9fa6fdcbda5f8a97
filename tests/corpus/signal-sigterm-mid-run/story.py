
import time, storyboard
class Slow(storyboard.Condition):
    def test_all(self, snapshot):
        time.sleep(0.05)  # a long run: the signal comes mid-run
        return snapshot.speeds < 0
def createStories(board):
    board.registerStory(storyboard.Story(Slow(), []))
