#include "sbsim/storyboard/geometry/Distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sbsim::storyboard::geometry {

namespace {

double pointToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d ab = b - a;
    const double length2 = ab.squaredNorm();
    if (length2 == 0) return (a - p).norm();  // a point's edge
    const double t = std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
    return (a + t * ab - p).norm();
}

}  // namespace

std::string_view distanceKindName(DistanceKind kind) {
    switch (kind) {
        case DistanceKind::Longitudinal:
            return "longitudinal";
        case DistanceKind::Lateral:
            return "lateral";
        case DistanceKind::Cartesian:
            return "cartesian";
    }
    return "cartesian";
}

double gap(const Footprint& a, const Footprint& b) {
    if (overlaps(a, b)) return 0;
    const auto ca = a.corners();
    const auto cb = b.corners();
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < 4; ++k) {
        for (const Eigen::Vector2d& p : cb) best = std::min(best, pointToSegment(p, ca[k], ca[(k + 1) % 4]));
        for (const Eigen::Vector2d& p : ca) best = std::min(best, pointToSegment(p, cb[k], cb[(k + 1) % 4]));
    }
    return best;
}

double distanceBetween(const Footprint& e, const Footprint& t, DistanceKind kind, bool freespace) {
    const Eigen::Vector2d d = t.centre() - e.centre();
    switch (kind) {
        case DistanceKind::Cartesian:
            return freespace ? gap(e, t) : d.norm();
        case DistanceKind::Longitudinal: {
            const double along = std::abs(d.dot(e.heading()));
            return freespace ? std::max(0.0, along - e.halfLength() - projectedHalfExtent(t, e.heading())) : along;
        }
        case DistanceKind::Lateral: {
            const double across = std::abs(d.dot(e.right()));
            return freespace ? std::max(0.0, across - e.halfWidth() - projectedHalfExtent(t, e.right())) : across;
        }
    }
    return d.norm();
}

}  // namespace sbsim::storyboard::geometry
