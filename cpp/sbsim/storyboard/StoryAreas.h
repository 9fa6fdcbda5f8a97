#pragma once

#include <Eigen/Core>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/ConditionArea.h"
#include "sbsim/storyboard/Story.h"

namespace sbsim::storyboard {

/// A place a story's condition tree ties it to (Condition::area), with the node it comes from:
/// what `sbsim check --json`, the report's map and the GUI draw.
struct SBSIM_API StoryArea : ConditionArea {
    /// The node the area comes from; owned by the story, so valid while the story lives.
    const Condition* condition = nullptr;
};

/// The areas of a condition tree, depth first in child order; a condition object reached along
/// several paths (shared sub-trees) yields its area once.
SBSIM_API std::vector<StoryArea> conditionAreas(const Condition& root);
/// The areas of a story's condition tree (see conditionAreas).
SBSIM_API std::vector<StoryArea> storyAreas(const Story& story);
/// The area as a polygon: its vertices, or a circle as `circleVertices` points on it (what SUMO,
/// which has no circles, draws).
SBSIM_API std::vector<Eigen::Vector2d> outline(const ConditionArea& area, int circleVertices = 36);

}  // namespace sbsim::storyboard
