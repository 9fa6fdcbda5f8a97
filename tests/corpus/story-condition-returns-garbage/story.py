
import storyboard
class C(storyboard.Condition):
    def test(self, vehicle):
        return object()
def createStories(board):
    board.registerStory(storyboard.Story(C(), []))
