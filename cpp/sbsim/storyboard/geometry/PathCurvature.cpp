#include "sbsim/storyboard/geometry/PathCurvature.h"

#include <cmath>
#include <numbers>

namespace sbsim::storyboard::geometry {

double PathCurvature::headingChange(double fromDeg, double toDeg) {
    // In degrees first: remainder is exact there, so a turn across north wraps without rounding.
    // SUMO's angles run clockwise, mathematical ones counter-clockwise: hence from - to.
    double change = std::remainder(fromDeg - toDeg, 360.0);  // [-180, 180]
    if (change == -180) change = 180;
    return change * (std::numbers::pi / 180);
}

double PathCurvature::of(const Eigen::Vector2d& previous, double previousDeg, const Eigen::Vector2d& current,
                         double currentDeg, double speed) {
    if (!(speed >= kMinSpeed)) return 0;
    const double distance = (current - previous).norm();
    if (!(distance >= kMinDistance)) return 0;
    const double curvature = headingChange(previousDeg, currentDeg) / distance;
    return std::abs(curvature) >= kMinCurvature ? curvature : 0;
}

}  // namespace sbsim::storyboard::geometry
