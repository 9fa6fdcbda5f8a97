#pragma once

#include <Eigen/Core>

#include "sbsim/kernel/Export.h"

namespace sbsim::storyboard {

/// Artery's canvas frame: origin at the network's top-left corner, y pointing down
/// (x_canvas = x_sumo − xmin, y_canvas = ymax − y_sumo), so Artery scripts' Coord values keep
/// their meaning. Built from SUMO's network boundary.
class SBSIM_API CanvasFrame {
public:
    CanvasFrame() = default;
    /// `boundary`: columns (xmin, ymin) and (xmax, ymax), as SumoBridge::netBoundary().
    explicit CanvasFrame(const Eigen::Matrix2d& boundary) : xmin_(boundary(0, 0)), ymax_(boundary(1, 1)) {}

    Eigen::Vector2d toSumo(const Eigen::Vector2d& canvas) const { return {canvas.x() + xmin_, ymax_ - canvas.y()}; }
    Eigen::Vector2d toCanvas(const Eigen::Vector2d& sumo) const { return {sumo.x() - xmin_, ymax_ - sumo.y()}; }

private:
    double xmin_ = 0;
    double ymax_ = 0;
};

}  // namespace sbsim::storyboard
