#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/storyboard/Story.h"

namespace sbsim::storyboard {

/// A place a story's conditions name, as an outline in SUMO's frame (what `sbsim --gui` draws).
struct SBSIM_API StoryArea {
    std::size_t story = 0;  ///< registration index (its colour: storyColour(story))
    std::string name;       ///< the story's name
    std::vector<Eigen::Vector2d> outline;
};

/// Every area of every story, in story order and then depth-first through each condition tree:
/// a PolygonCondition's polygon (already in SUMO's frame, whichever frame the script wrote it in)
/// and a DistanceCondition's circle around a fixed point (as a polygon of `circleVertices`
/// points). A node shared within one story's tree gives one area.
SBSIM_API std::vector<StoryArea> storyAreas(const std::vector<StoryPtr>& stories, int circleVertices = 36);

}  // namespace sbsim::storyboard
