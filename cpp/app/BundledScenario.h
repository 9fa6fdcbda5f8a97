#pragma once

#include <filesystem>
#include <optional>

namespace sbsim::app {

/// The scenario `sbsim` runs without --sumocfg: stories/grid-rain, looked up next to the installed
/// program (<prefix>/share/sbsim/stories) and then in the source tree it was built from.
struct BundledScenario {
    std::filesystem::path sumocfg;
    std::optional<std::filesystem::path> story;  ///< its story.py, when it has one

    /// Throws std::runtime_error naming the places searched if no copy is found.
    static BundledScenario locate();
};

}  // namespace sbsim::app
