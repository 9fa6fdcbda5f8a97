
import storyboard
kept = []
class C(storyboard.Condition):
    def test_all(self, snapshot):
        kept.append(snapshot.speeds)
        total = sum(float(a.sum()) for a in kept[-5:])
        return snapshot.speeds < -1
def createStories(board):
    board.registerStory(storyboard.Story(C(), []))
