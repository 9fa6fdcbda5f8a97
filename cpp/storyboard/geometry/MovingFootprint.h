#pragma once

#include <cmath>
#include <limits>

#include "storyboard/geometry/Footprint.h"

namespace sbsim::storyboard::geometry {

/// A footprint driving straight on at constant speed, with what the time-to-collision test needs
/// of it worked out once per step rather than once per pair.
struct MovingFootprint {
    MovingFootprint(const Footprint& f, double speedAlongHeading)
        : footprint(f),
          speed(speedAlongHeading),
          velocity(speedAlongHeading * f.heading()),
          radius(std::hypot(f.halfLength(), f.halfWidth())),
          sampleStep(speedAlongHeading != 0 ? 2 * f.halfLength() / std::abs(speedAlongHeading)
                                            : std::numeric_limits<double>::infinity()) {}

    Footprint footprint;
    double speed;              ///< m/s along the heading (negative: backwards)
    Eigen::Vector2d velocity;  ///< speed · heading
    double radius;             ///< of the circle around the footprint's centre that holds it
    double sampleStep;         ///< s to drive one length; infinite when standing
};

}  // namespace sbsim::storyboard::geometry
