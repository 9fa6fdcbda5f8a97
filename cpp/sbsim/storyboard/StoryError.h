#pragma once

#include <stdexcept>
#include <string>

#include "sbsim/kernel/Export.h"

namespace sbsim::storyboard {

/// A story script failed (syntax error, missing createStories, an exception in it or in a custom
/// condition or effect, a wrong argument). what() is one line naming the script's file and line;
/// details() is the Python traceback, if any. The program exits with code 2.
class SBSIM_API StoryError : public std::runtime_error {
public:
    StoryError(const std::string& message, std::string details = {})
        : std::runtime_error(message), details_(std::move(details)) {}
    const std::string& details() const { return details_; }

private:
    std::string details_;
};

}  // namespace sbsim::storyboard
