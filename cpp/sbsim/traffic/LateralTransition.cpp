#include "sbsim/traffic/LateralTransition.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sbsim::traffic {

double LateralPlace::across(const std::vector<double>& widths) const {
    if (widths.empty()) return offset;
    const auto last = static_cast<int>(widths.size()) - 1;
    const int index = std::clamp(lane, 0, last);
    double edge = 0;
    for (int i = 0; i < index; ++i) edge += widths[static_cast<std::size_t>(i)];
    return edge + widths[static_cast<std::size_t>(index)] / 2 + offset;
}

LateralTransition LateralTransition::withMaxAcceleration(Transition::Shape shape, double maxAcceleration,
                                                         LateralPlace target) {
    LateralTransition transition({shape, Transition::Dimension::Time, 0}, target);
    transition.maxAcceleration_ = maxAcceleration;
    return transition;
}

double LateralTransition::next(double now, double dt, const LateralPlace& place, const std::vector<double>& widths,
                               double speed, double driven) {
    if (!started_) {
        started_ = true;
        start_ = place;
        startTime_ = now;
        startDriven_ = driven;
        if (maxAcceleration_ && *maxAcceleration_ > 0) {
            const double d = std::abs(target_.across(widths) - place.across(widths));
            dynamics_.value = dynamics_.shape == Transition::Shape::Sinusoidal
                                  ? std::numbers::pi * std::sqrt(d / (2 * *maxAcceleration_))
                                  : std::sqrt(6 * d / *maxAcceleration_);
        }
    }
    const double from = start_.across(widths);
    const double to = target_.across(widths);
    const double progress = dynamics_.progress(now + dt - startTime_, driven - startDriven_ + speed * dt, to - from);
    if (progress >= 1) *reached_ = true;
    const double wanted = from + (to - from) * Transition::shaped(dynamics_.shape, progress);
    return wanted - place.across(widths);
}

}  // namespace sbsim::traffic
