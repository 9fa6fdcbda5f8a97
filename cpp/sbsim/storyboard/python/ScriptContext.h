#pragma once

#include <pybind11/pybind11.h>

#include <filesystem>
#include <string>

#include "sbsim/storyboard/CanvasFrame.h"
#include "sbsim/storyboard/Storyboard.h"

namespace sbsim::storyboard {

/// What the Python bindings need from the running program: the board, the canvas frame for
/// Coord, and the script's path for error messages. Set by StoryScript while it lives.
struct ScriptContext {
    Storyboard* board = nullptr;
    CanvasFrame frame;
    std::filesystem::path script;

    static ScriptContext& current();
};

/// Turns the active Python exception into a StoryError: one line "file:line: Type: message"
/// (the innermost frame in the story script, else in any file) plus the full traceback.
[[noreturn]] void throwStoryError(pybind11::error_already_set& error, const std::string& during);

/// A custom condition or effect broke the story API's contract (say, test() returned an int):
/// a StoryError naming the file and line where the object's class is defined.
[[noreturn]] void throwContractError(const pybind11::handle& object, const std::string& message);

}  // namespace sbsim::storyboard
