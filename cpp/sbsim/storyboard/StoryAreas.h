#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/Story.h"

namespace sbsim::storyboard {

/// A place a story's condition tree ties it to, in SUMO's network frame whatever frame the script
/// wrote it in (the bindings convert Coord points when the condition is built). What `sbsim check
/// --json`, the report's map and the GUI draw.
struct SBSIM_API StoryArea {
    /// The node the area comes from; owned by the story, so valid while the story lives.
    const Condition* condition = nullptr;
    /// A polygon's vertices (as given, not closed), or a circle's centre.
    std::vector<Eigen::Vector2d> points;
    /// Set for a circle: a DistanceCondition around a fixed point (m).
    std::optional<double> radius;
};

/// The areas of a condition tree, depth first in child order; a condition object reached along
/// several paths (shared sub-trees) yields its area once.
SBSIM_API std::vector<StoryArea> conditionAreas(const Condition& root);
/// The areas of a story's condition tree (see conditionAreas).
SBSIM_API std::vector<StoryArea> storyAreas(const Story& story);
/// The area as a polygon: its vertices, or a circle as `circleVertices` points on it (what SUMO,
/// which has no circles, draws).
SBSIM_API std::vector<Eigen::Vector2d> outline(const StoryArea& area, int circleVertices = 36);

}  // namespace sbsim::storyboard
