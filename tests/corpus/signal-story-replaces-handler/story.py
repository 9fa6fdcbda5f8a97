
import signal, time, storyboard
class Slow(storyboard.Condition):
    def test_all(self, snapshot):
        time.sleep(0.05)
        return snapshot.speeds < 0
def createStories(board):
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    board.registerStory(storyboard.Story(Slow(), []))
