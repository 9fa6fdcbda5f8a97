#include "sbsim/storyboard/effects/LaneOffsetEffect.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/traffic/LateralTransition.h"

namespace sbsim::storyboard {

LaneOffsetEffect::LaneOffsetEffect(double offset, traffic::Transition dynamics,
                                   std::optional<double> maxLateralAcceleration, std::optional<std::string> relativeTo,
                                   bool continuous)
    : offset_(offset),
      dynamics_(dynamics),
      maxLateralAcceleration_(maxLateralAcceleration),
      relativeTo_(std::move(relativeTo)),
      continuous_(continuous) {
    if (relativeTo_ && relativeTo_->empty()) throw std::invalid_argument("LaneOffsetEffect: the vehicle id is empty");
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
    const double offset = offset_ + (relativeTo_ ? scope.controllerOf(*relativeTo_)->lateralLanePosition() : 0.0);
    const traffic::LateralPlace target{scope.vehicle().laneIndex(), offset};
    traffic::LateralTransition transition =
        maxLateralAcceleration_
            ? traffic::LateralTransition::withMaxAcceleration(dynamics_.shape, *maxLateralAcceleration_, target)
            : traffic::LateralTransition(dynamics_, target);
    reached_.track(scope.token(), transition.reachedFlag());
    scope.stack().pushLateralTransition(scope.token(), std::move(transition));
}

std::string LaneOffsetEffect::describe() const {
    const std::string offset =
        relativeTo_ ? fmt::format("{}'s offset {:+g} m", *relativeTo_, offset_) : fmt::format("{:+g} m", offset_);
    const std::string held = continuous_ ? ", held" : "";
    if (maxLateralAcceleration_) {
        return fmt::format("LaneOffsetEffect({}, {} at most {:g} m/s²{})", offset,
                           traffic::Transition::name(dynamics_.shape), *maxLateralAcceleration_, held);
    }
    return fmt::format("LaneOffsetEffect({}, {}{})", offset, dynamics_.describe("m/s"), held);
}

void LaneOffsetEffect::check(CheckContext& ctx) const {
    if (relativeTo_ && !ctx.vehicleDefined(*relativeTo_)) {
        ctx.warn(fmt::format("{} is relative to vehicle '{}', which no route file or story defines", typeName(),
                             *relativeTo_));
    }
}

}  // namespace sbsim::storyboard
