#pragma once

#include <filesystem>
#include <memory>

#include "sbsim/kernel/Export.h"
#include "sbsim/python/PythonRuntime.h"
#include "sbsim/storyboard/CanvasFrame.h"
#include "sbsim/storyboard/Storyboard.h"

namespace sbsim::storyboard {

/// A story script run by the embedded interpreter: imports the file (its folder first on
/// sys.path) and calls its createStories(board) — or createStories() with a module-level `board`,
/// as Artery's scripts expect. Every Python failure becomes a StoryError naming file and line.
class SBSIM_API StoryScript {
public:
    /// `python` must outlive the board: stories keep Python objects alive.
    StoryScript(python::PythonRuntime& python, const std::filesystem::path& script, Storyboard& board,
                const CanvasFrame& frame);
    ~StoryScript();

    /// Imports the script and runs createStories. Returns the number of stories registered.
    std::size_t createStories();

private:
    std::filesystem::path script_;
    Storyboard& board_;
    CanvasFrame frame_;
    python::PythonRuntime& python_;
};

}  // namespace sbsim::storyboard
