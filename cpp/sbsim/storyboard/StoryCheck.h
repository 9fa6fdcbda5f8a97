#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/Effect.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/WorldEffect.h"

namespace sbsim::storyboard {

/// What `sbsim check` knows of the scenario a story set will run in.
struct SBSIM_API CheckScenario {
    Eigen::Matrix2d boundary = Eigen::Matrix2d::Zero();  ///< SUMO's net boundary: (xmin, ymin), (xmax, ymax)
    kernel::SimTime begin;
    std::optional<kernel::SimTime> end;
    /// Whether a route file defines this vehicle id (flows: "<flow id>.<n>").
    std::function<bool(std::string_view)> vehicleDefined;
};

/// One thing that looks wrong in a story; the run would not fail, but likely not do what was meant.
struct SBSIM_API CheckWarning {
    std::string story;
    std::string message;
};

/// One node of a story as `sbsim check` prints it: a condition or effect with its parameters.
struct SBSIM_API DescribedNode {
    int depth = 0;
    std::string text;
};

/// A condition or effect in one line: its class name and parameters, e.g. "TimeCondition(120 s, 420 s)".
SBSIM_API std::string describe(const Condition& condition);
SBSIM_API std::string describe(const Effect& effect);
SBSIM_API std::string describe(const WorldEffect& effect);
/// The story's condition tree (children indented one level) and then its effects (a WorldStory's
/// world effects, after a first line "world story: acts on the network").
SBSIM_API std::vector<DescribedNode> describeStory(const Story& story);
/// The warnings `sbsim check` gives for a story set, in story order.
SBSIM_API std::vector<CheckWarning> checkStories(const std::vector<StoryPtr>& stories, const CheckScenario& scenario);

}  // namespace sbsim::storyboard
