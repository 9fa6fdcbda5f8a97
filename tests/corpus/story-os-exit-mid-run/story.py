
import os, storyboard
class C(storyboard.Condition):
    def test(self, vehicle):
        if vehicle.time >= 5:
            os._exit(0)
        return False
def createStories(board):
    board.registerStory(storyboard.Story(C(), []))
