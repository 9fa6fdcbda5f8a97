#pragma once

#include <Eigen/Core>

#include "sbsim/kernel/Export.h"

namespace sbsim::facilities {

/// A geo-broadcast destination area (GeoNetworking's circle), in SUMO's network frame (m).
struct SBSIM_API GeoCircle {
    Eigen::Vector2d center = Eigen::Vector2d::Zero();
    double radius = 0;  ///< m

    /// Whether `point` lies inside or on the circle.
    bool contains(const Eigen::Vector2d& point) const;
};

}  // namespace sbsim::facilities
