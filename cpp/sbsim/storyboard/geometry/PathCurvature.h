#pragma once

#include <Eigen/Core>

namespace sbsim::storyboard::geometry {

/// The curvature a vehicle drove with between two snapshots, as Artery's time-to-collision test
/// uses it to predict a vehicle on a bend along a circle instead of a straight line.
struct PathCurvature {
    /// Slower vehicles (m/s) get no curvature: their heading is too noisy.
    static constexpr double kMinSpeed = 1;
    /// Positions closer than this (m) give no curvature: the division by the distance would blow up.
    static constexpr double kMinDistance = 0.01;
    /// Gentler curvatures (1/m, a radius above 2.5 km) count as straight.
    static constexpr double kMinCurvature = 1.0 / 2500;

    /// The heading change (radians, counter-clockwise positive, in (-pi, pi]) from SUMO angle
    /// `fromDeg` to `toDeg` (degrees, clockwise from north).
    static double headingChange(double fromDeg, double toDeg);

    /// The signed curvature (1/m, positive turning left) of a vehicle whose front bumper moved
    /// from `previous` (SUMO angle `previousDeg`) to `current` (`currentDeg`) and which now drives
    /// at `speed`: the heading change over the straight distance driven. 0 (drive straight) when
    /// speed < kMinSpeed, the distance < kMinDistance or |curvature| < kMinCurvature.
    static double of(const Eigen::Vector2d& previous, double previousDeg, const Eigen::Vector2d& current,
                     double currentDeg, double speed);
};

}  // namespace sbsim::storyboard::geometry
