#include "sbsim/services/ca/CamGenerationRules.h"

#include <algorithm>
#include <cmath>

namespace sbsim::services {

CamGenerationRules::CamGenerationRules(CamRuleSettings settings) : settings_(settings), genCam_(settings.maxInterval) {}

double CamGenerationRules::headingDifference(double a, double b) {
    const double d = std::fmod(std::abs(a - b), 360.0);
    return d > 180.0 ? 360.0 - d : d;
}

kernel::SimTime CamGenerationRules::genCamDcc(std::optional<kernel::SimTime> dccInterval) const {
    if (!dccInterval) return settings_.minInterval;
    return std::clamp(*dccInterval, settings_.minInterval, settings_.maxInterval);
}

void CamGenerationRules::sent(kernel::SimTime now, const CamDynamics& current) {
    lastTime_ = now;
    last_ = current;
}

CamGenerationRules::Reason CamGenerationRules::check(kernel::SimTime now, const CamDynamics& current,
                                                     std::optional<kernel::SimTime> dccInterval) {
    if (!lastTime_) {
        sent(now, current);
        return Reason::First;
    }
    const kernel::SimTime elapsed = now - *lastTime_;
    if (elapsed < genCamDcc(dccInterval)) return Reason::None;
    if (settings_.fixedRate) {
        sent(now, current);
        return Reason::FixedRate;
    }
    const bool dynamics = headingDifference(last_.heading, current.heading) > settings_.headingDelta ||
                          (current.position - last_.position).norm() > settings_.positionDelta ||
                          std::abs(current.speed - last_.speed) > settings_.speedDelta;
    if (dynamics) {
        sent(now, current);
        // A middleware interval longer than Max would otherwise set T_GenCam above it.
        genCam_ = std::min(elapsed, settings_.maxInterval);
        lowDynamicsCount_ = 0;
        return Reason::Dynamics;
    }
    if (elapsed >= genCam_) {
        sent(now, current);
        if (++lowDynamicsCount_ >= settings_.lowDynamicsLimit) genCam_ = settings_.maxInterval;
        return Reason::Timeout;
    }
    return Reason::None;
}

}  // namespace sbsim::services
