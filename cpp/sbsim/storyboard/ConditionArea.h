#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace sbsim::storyboard {

/// The frame a script wrote a place in: SUMO's network frame ((x, y) tuples) or Artery's canvas
/// frame (Coord, origin at the boundary's top-left, y downwards). Places are stored in SUMO's.
enum class GivenFrame { Sumo, Canvas };

/// A place a condition ties its story to, in SUMO's network frame whatever frame the script wrote
/// it in (the bindings convert Coord points when the condition is built).
struct ConditionArea {
    /// A polygon's vertices (as given, not closed), or a circle's centre.
    std::vector<Eigen::Vector2d> points;
    /// Set for a circle (m).
    std::optional<double> radius;
    /// The frame the script wrote it in, so `sbsim check` can say which frame would have fitted.
    GivenFrame given = GivenFrame::Sumo;
};

}  // namespace sbsim::storyboard
