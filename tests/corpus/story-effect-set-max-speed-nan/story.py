
import storyboard
class E(storyboard.Effect):
    def apply(self, vehicle):
        vehicle.set_max_speed(float('nan'))
    def reapply(self, vehicle):
        pass
    def remove(self, vehicle):
        pass
def createStories(board):
    board.registerStory(storyboard.Story(storyboard.TimeCondition(1), [E()]))
