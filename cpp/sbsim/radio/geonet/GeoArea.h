#pragma once

#include <Eigen/Core>

#include "sbsim/kernel/Export.h"

namespace sbsim::radio::geonet {

/// A GeoNetworking destination area: a circle in SUMO's network frame (m). (EN 302 636-4-1 also
/// defines rectangles and ellipses; sbsim's DENMs use circles only.)
struct SBSIM_API GeoArea {
    Eigen::Vector2d center = Eigen::Vector2d::Zero();
    double radius = 0;  ///< m

    /// Whether `point` lies inside or on the border (the standard's F(x, y) >= 0).
    bool contains(const Eigen::Vector2d& point) const { return (point - center).squaredNorm() <= radius * radius; }
};

}  // namespace sbsim::radio::geonet
