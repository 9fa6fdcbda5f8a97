#pragma once

#include <cmath>
#include <limits>

#include "sbsim/storyboard/geometry/Footprint.h"

namespace sbsim::storyboard::geometry {

/// The circle around a footprint's centre that holds it, moving with the vehicle: the compact
/// part of a MovingFootprint that the cheap first test of a time-to-collision pair reads.
struct MovingCircle {
    Eigen::Vector2d centre;
    Eigen::Vector2d velocity;  ///< m/s
    double radius;             ///< m
    double sampleStep;         ///< s to drive one own length; infinite when standing
    double curvature;          ///< 1/m of the arc it drives on; 0: straight along `velocity`
};

/// Whether two moving circles come within touching distance at some t in [0, horizon]: the
/// closest approach of the centres, worked out without a division. Pairs within 0.1 mm count as
/// meeting, far above rounding error, so a false answer is safe to act on.
inline bool mayMeet(const MovingCircle& a, const MovingCircle& b, double horizon) {
    constexpr double kSlack = 1e-4;
    const Eigen::Vector2d d0 = b.centre - a.centre;
    const Eigen::Vector2d w = b.velocity - a.velocity;
    const double reach = a.radius + b.radius + kSlack;
    const double reach2 = reach * reach;
    const double dd = d0.squaredNorm();
    const double dw = d0.dot(w);
    if (!(dw < 0)) return !(dd > reach2);  // closest now: moving apart or keeping the distance
    const double ww = w.squaredNorm();
    if (ww * horizon <= -dw) return !((d0 + horizon * w).squaredNorm() > reach2);  // still closing then
    return !((dd - reach2) * ww > dw * dw);  // the closest approach is dd - dw²/ww
}

/// A footprint driving on at constant speed, straight or (curvature != 0) along a circular arc
/// from its centre, with what the time-to-collision test needs of it worked out once per step
/// rather than once per pair.
struct MovingFootprint {
    MovingFootprint(const Footprint& f, double speedAlongHeading, double pathCurvature = 0)
        : footprint(f),
          speed(speedAlongHeading),
          curvature(pathCurvature),
          circle{f.centre(), speedAlongHeading * f.heading(), std::hypot(f.halfLength(), f.halfWidth()),
                 speedAlongHeading != 0 ? 2 * f.halfLength() / std::abs(speedAlongHeading)
                                        : std::numeric_limits<double>::infinity(),
                 pathCurvature} {}

    /// The footprint after `seconds`.
    Footprint at(double seconds) const {
        return curvature == 0 ? footprint.movedFor(speed, seconds) : footprint.turnedFor(speed, curvature, seconds);
    }

    /// at(seconds).centre(), without the heading.
    Eigen::Vector2d centreAt(double seconds) const {
        return curvature == 0 ? footprint.movedFor(speed, seconds).centre()
                              : footprint.turnedCentre(speed * seconds, curvature);
    }

    Footprint footprint;
    double speed;      ///< m/s along the heading (negative: backwards)
    double curvature;  ///< 1/m, positive turning left; 0: straight
    MovingCircle circle;
};

}  // namespace sbsim::storyboard::geometry
