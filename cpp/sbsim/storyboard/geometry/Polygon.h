#pragma once

#include <Eigen/Core>
#include <vector>

namespace sbsim::storyboard::geometry {

/// A simple or non-convex polygon in the plane (even-odd rule), any orientation. Points exactly on
/// an edge or a vertex are outside, so two polygons sharing an edge never both contain a point.
class Polygon {
public:
    /// Throws std::invalid_argument for fewer than 3 vertices or a non-finite coordinate. The ring
    /// closes itself; repeating the first vertex at the end is allowed.
    explicit Polygon(std::vector<Eigen::Vector2d> vertices);

    const std::vector<Eigen::Vector2d>& vertices() const { return vertices_; }
    bool contains(const Eigen::Vector2d& p) const;
    /// Whether the ring is its own bounding box (four corners, edges along the axes): then a point
    /// is inside exactly when it is strictly inside the box, which contains() answers at once.
    bool isBox() const { return box_; }

private:
    std::vector<Eigen::Vector2d> vertices_;
    Eigen::Vector2d min_, max_;  // bounding box, for a quick rejection
    bool box_ = false;
};

}  // namespace sbsim::storyboard::geometry
