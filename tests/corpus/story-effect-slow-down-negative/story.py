
import storyboard
class E(storyboard.Effect):
    def apply(self, vehicle):
        vehicle.slow_down(5, -10)
    def reapply(self, vehicle):
        pass
    def remove(self, vehicle):
        pass
def createStories(board):
    board.registerStory(storyboard.Story(storyboard.TimeCondition(1), [E()]))
