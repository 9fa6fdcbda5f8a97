#pragma once

#include <filesystem>
#include <optional>

namespace sbsim::app {

/// The scenario `sbsim` runs without --sumocfg: stories/grid-rain, looked up where the install put
/// it (<site-packages>/sbsim/share/stories, or <prefix>/share/sbsim/stories) and then in the
/// source tree the program was built from.
struct BundledScenario {
    std::filesystem::path sumocfg;
    std::optional<std::filesystem::path> story;  ///< its story.py, when it has one

    /// Throws std::runtime_error naming the places searched if no copy is found.
    static BundledScenario locate();
};

}  // namespace sbsim::app
