
import storyboard
class C(storyboard.Condition):
    def test(self, vehicle):
        while True:
            pass
def createStories(board):
    board.registerStory(storyboard.Story(C(), []))
