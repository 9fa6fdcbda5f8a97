
import storyboard
kept = []
class E(storyboard.Effect):
    def apply(self, vehicle):
        kept.append(vehicle)
    def reapply(self, vehicle):
        pass
    def remove(self, vehicle):
        pass
class C(storyboard.Condition):
    def test(self, vehicle):
        for v in kept[:50]:
            v.set_max_speed(10.0)
        return True
def createStories(board):
    board.registerStory(storyboard.Story(C(), [E()]))
