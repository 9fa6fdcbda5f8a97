#include "sbsim/storyboard/geometry/Footprint.h"

#include <cmath>
#include <numbers>

namespace sbsim::storyboard::geometry {

Eigen::Vector2d Footprint::headingOf(double sumoAngleDeg) {
    double a = std::fmod(sumoAngleDeg, 360.0);
    if (a < 0) a += 360.0;
    // Roads along the axes are common; exact unit vectors there keep touching shapes touching.
    if (a == 0) return {0, 1};
    if (a == 90) return {1, 0};
    if (a == 180) return {0, -1};
    if (a == 270) return {-1, 0};
    const double rad = a * (std::numbers::pi / 180);
    return {std::sin(rad), std::cos(rad)};
}

Footprint Footprint::fromSumo(const Eigen::Vector2d& frontBumper, double sumoAngleDeg, double length, double width) {
    const Eigen::Vector2d heading = headingOf(sumoAngleDeg);
    return {frontBumper - (0.5 * length) * heading, heading, length, width};
}

Footprint Footprint::turned(double distance, double curvature) const {
    const double angle = curvature * distance;  // radians turned, counter-clockwise
    const double sin = std::sin(angle);
    Footprint f = *this;
    f.centre_ = centreOnArc(angle, sin, curvature);
    f.heading_ = std::cos(angle) * heading_ + sin * -right();  // turned left by `angle`
    return f;
}

Eigen::Vector2d Footprint::turnedCentre(double distance, double curvature) const {
    const double angle = curvature * distance;
    return centreOnArc(angle, std::sin(angle), curvature);
}

Eigen::Vector2d Footprint::centreOnArc(double angle, double sin, double curvature) const {
    const double halfSin = std::sin(0.5 * angle);
    const Eigen::Vector2d left = -right();
    // The exact circle: sin(κs)/κ along the heading, (1 - cos κs)/κ = 2 sin²(κs/2)/κ to the left
    // (the half-angle form keeps precision on gentle curves, where 1 - cos κs cancels).
    return centre_ + ((sin / curvature) * heading_ + (2 * halfSin * halfSin / curvature) * left);
}

std::array<Eigen::Vector2d, 4> Footprint::corners() const {
    const Eigen::Vector2d l = halfLength_ * heading_;
    const Eigen::Vector2d w = halfWidth_ * right();
    return {centre_ + l - w, centre_ + l + w, centre_ - l + w, centre_ - l - w};
}

double projectedHalfExtent(const Footprint& f, const Eigen::Vector2d& axis) {
    return f.halfLength() * std::abs(f.heading().dot(axis)) + f.halfWidth() * std::abs(f.right().dot(axis));
}

bool overlaps(const Footprint& a, const Footprint& b) {
    // Two rectangles are disjoint iff their projections are disjoint on one of their four edge
    // normals; a gap up to the tolerance still counts as touching.
    const Eigen::Vector2d d = b.centre() - a.centre();
    const Eigen::Vector2d axes[] = {a.heading(), a.right(), b.heading(), b.right()};
    for (const Eigen::Vector2d& axis : axes) {
        const double gap = std::abs(d.dot(axis)) - projectedHalfExtent(a, axis) - projectedHalfExtent(b, axis);
        if (gap > Footprint::kTouchTolerance) return false;
    }
    return true;
}

}  // namespace sbsim::storyboard::geometry
