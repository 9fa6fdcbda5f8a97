#include "sbsim/storyboard/geometry/Polygon.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sbsim::storyboard::geometry {

namespace {
/// Whether the ring, without a repeated closing vertex, is the box's four corners in order round
/// it (each edge along an axis). A ring that goes round twice, or crosses itself, is not. The box
/// must not be so thin that the boundary test's products could underflow to zero.
bool isItsBox(const std::vector<Eigen::Vector2d>& ring, const Eigen::Vector2d& min, const Eigen::Vector2d& max) {
    std::size_t n = ring.size();
    if (n == 5 && ring.front() == ring.back()) n = 4;
    if (n != 4 || !((max - min).minCoeff() > 1e-100)) return false;
    int corners = 0;  // bit per corner: x at max is 1, y at max is 2
    for (std::size_t k = 0; k < 4; ++k) {
        const Eigen::Vector2d& v = ring[k];
        const Eigen::Vector2d& w = ring[(k + 1) % 4];
        if ((v.x() != min.x() && v.x() != max.x()) || (v.y() != min.y() && v.y() != max.y())) return false;
        if (v.x() != w.x() && v.y() != w.y()) return false;  // a diagonal: crossing itself
        corners |= 1 << ((v.x() == max.x() ? 1 : 0) + (v.y() == max.y() ? 2 : 0));
    }
    return corners == 0b1111;
}
}  // namespace

Polygon::Polygon(std::vector<Eigen::Vector2d> vertices) : vertices_(std::move(vertices)) {
    if (vertices_.size() < 3) {
        throw std::invalid_argument(fmt::format("a polygon needs at least 3 vertices, got {}", vertices_.size()));
    }
    min_ = max_ = vertices_.front();
    for (const Eigen::Vector2d& v : vertices_) {
        if (!v.allFinite()) throw std::invalid_argument("polygon vertex with a non-finite coordinate");
        min_ = min_.cwiseMin(v);
        max_ = max_.cwiseMax(v);
    }
    box_ = isItsBox(vertices_, min_, max_);
}

bool Polygon::contains(const Eigen::Vector2d& p) const {
    // Outside the box, or on it (a box edge touches the polygon only at its boundary).
    if (!(p.x() > min_.x() && p.x() < max_.x() && p.y() > min_.y() && p.y() < max_.y())) return false;
    // Strictly inside a box ring: off every edge, and a ray towards +x crosses only the right one.
    if (box_) return true;
    bool inside = false;
    const std::size_t n = vertices_.size();
    for (std::size_t k = 0, prev = n - 1; k < n; prev = k++) {
        const Eigen::Vector2d& a = vertices_[prev];
        const Eigen::Vector2d& b = vertices_[k];
        // On the segment a-b: collinear and within its extent. Checked first, so the crossing
        // count below never has to decide about boundary points.
        const double cross = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
        if (cross == 0 && p.x() >= std::min(a.x(), b.x()) && p.x() <= std::max(a.x(), b.x()) &&
            p.y() >= std::min(a.y(), b.y()) && p.y() <= std::max(a.y(), b.y())) {
            return false;
        }
        // Crossing of a ray towards +x; the half-open rule (a.y > p.y) != (b.y > p.y) counts a
        // vertex on the ray exactly once and skips horizontal edges.
        if ((a.y() > p.y()) != (b.y() > p.y())) {
            const double xCross = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
            if (p.x() < xCross) inside = !inside;
        }
    }
    return inside;
}

}  // namespace sbsim::storyboard::geometry
