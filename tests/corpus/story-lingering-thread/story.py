
import threading, time, storyboard
def createStories(board):
    threading.Thread(target=lambda: time.sleep(3600)).start()
    board.registerStory(storyboard.Story(storyboard.TimeCondition(1), [storyboard.SignalEffect('x')]))
