
import storyboard
class C(storyboard.Condition):
    def test(self, vehicle):
        if vehicle.time >= 5:
            raise RuntimeError('mid-run failure')
        return False
def createStories(board):
    board.registerStory(storyboard.Story(C(), []))
