#include "sbsim/traffic/SpeedTransition.h"

#include <algorithm>

namespace sbsim::traffic {

double SpeedTransition::target() {
    if (target_.kind == SpeedTarget::Kind::Absolute) return target_.value;
    if (started_ && !target_.continuous) return lastTarget_;
    const std::optional<double> reference = target_.reference ? target_.reference() : std::nullopt;
    if (!reference) return lastTarget_;  // the reference left: its last speed stands
    const double value =
        target_.kind == SpeedTarget::Kind::Delta ? *reference + target_.value : *reference * target_.value;
    lastTarget_ = std::max(0.0, value);
    return lastTarget_;
}

double SpeedTransition::next(double now, double dt, double speed, double driven) {
    if (!started_) {
        lastTarget_ = speed;  // a reference not running at the start: the vehicle keeps its speed
        const double first = target();
        started_ = true;
        startTime_ = now;
        startSpeed_ = speed;
        startDriven_ = driven;
        startDelta_ = first - speed;
    }
    const double goal = target();
    // Progress at the end of the coming step; by distance, it drives about `speed` m/s meanwhile.
    const double progress = dynamics_.progress(now + dt - startTime_, driven - startDriven_ + speed * dt, startDelta_);
    if (progress >= 1) outcome_->reached = true;
    outcome_->target = goal;
    return startSpeed_ + (goal - startSpeed_) * Transition::shaped(dynamics_.shape, progress);
}

}  // namespace sbsim::traffic
