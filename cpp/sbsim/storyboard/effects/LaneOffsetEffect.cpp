#include "sbsim/storyboard/effects/LaneOffsetEffect.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sbsim/traffic/LateralTransition.h"

namespace sbsim::storyboard {

LaneOffsetEffect::LaneOffsetEffect(double offset, traffic::Transition dynamics,
                                   std::optional<double> maxLateralAcceleration)
    : offset_(offset), dynamics_(dynamics), maxLateralAcceleration_(maxLateralAcceleration) {
    if (!std::isfinite(offset)) throw std::invalid_argument("LaneOffsetEffect needs a finite offset in m");
    if (!std::isfinite(dynamics.value) || dynamics.value < 0) {
        throw std::invalid_argument(
            fmt::format("LaneOffsetEffect needs a transition value >= 0, got {:f}", dynamics.value));
    }
    if (maxLateralAcceleration && !(std::isfinite(*maxLateralAcceleration) && *maxLateralAcceleration > 0)) {
        throw std::invalid_argument(
            fmt::format("LaneOffsetEffect needs a max lateral acceleration > 0, got {:f}", *maxLateralAcceleration));
    }
}

void LaneOffsetEffect::apply(EffectScope& scope) {
    const traffic::LateralPlace target{scope.vehicle().laneIndex(), offset_};
    traffic::LateralTransition transition =
        maxLateralAcceleration_
            ? traffic::LateralTransition::withMaxAcceleration(dynamics_.shape, *maxLateralAcceleration_, target)
            : traffic::LateralTransition(dynamics_, target);
    reached_.track(scope.token(), transition.reachedFlag());
    scope.stack().pushLateralTransition(scope.token(), std::move(transition));
}

std::string LaneOffsetEffect::describe() const {
    if (maxLateralAcceleration_) {
        return fmt::format("LaneOffsetEffect({:+g} m, {} at most {:g} m/s²)", offset_,
                           traffic::Transition::name(dynamics_.shape), *maxLateralAcceleration_);
    }
    return fmt::format("LaneOffsetEffect({:+g} m, {})", offset_, dynamics_.describe("m/s"));
}

}  // namespace sbsim::storyboard
