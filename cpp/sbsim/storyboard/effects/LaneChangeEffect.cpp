#include "sbsim/storyboard/effects/LaneChangeEffect.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/traffic/LateralTransition.h"

namespace sbsim::storyboard {

LaneChangeEffect::LaneChangeEffect(int lane, traffic::Transition dynamics, Relative relative,
                                   std::optional<std::string> relativeTo, double offset)
    : lane_(lane), dynamics_(dynamics), relative_(relative), relativeTo_(std::move(relativeTo)), offset_(offset) {
    if (relative_ == Relative::Absolute && lane < 0) {
        throw std::invalid_argument(fmt::format("LaneChangeEffect: lane index must be >= 0, not {}", lane));
    }
    if ((relative_ == Relative::Vehicle) != relativeTo_.has_value() || (relativeTo_ && relativeTo_->empty())) {
        throw std::invalid_argument("LaneChangeEffect: a lane relative to a vehicle needs that vehicle's id");
    }
    if (!std::isfinite(dynamics.value) || dynamics.value < 0 || !std::isfinite(offset)) {
        throw std::invalid_argument(
            fmt::format("LaneChangeEffect needs a transition value >= 0, got {:f}", dynamics.value));
    }
}

void LaneChangeEffect::apply(EffectScope& scope) {
    int lane = lane_;
    if (relative_ == Relative::Self) lane += scope.vehicle().laneIndex();
    if (relative_ == Relative::Vehicle) lane += scope.controllerOf(*relativeTo_)->laneIndex();
    traffic::LateralTransition transition(dynamics_, traffic::LateralPlace{lane, offset_});
    reached_.track(scope.token(), transition.reachedFlag());
    scope.stack().pushLateralTransition(scope.token(), std::move(transition));
}

std::string LaneChangeEffect::describe() const {
    std::string target;
    switch (relative_) {
        case Relative::Absolute:
            target = fmt::format("lane {}", lane_);
            break;
        case Relative::Self:
            target = fmt::format("own lane {:+d}", lane_);
            break;
        case Relative::Vehicle:
            target = fmt::format("{}'s lane {:+d}", *relativeTo_, lane_);
            break;
    }
    const std::string offset = offset_ != 0 ? fmt::format(" {:+g} m", offset_) : "";
    return fmt::format("LaneChangeEffect({}{}, {})", target, offset, dynamics_.describe("m/s"));
}

void LaneChangeEffect::check(CheckContext& ctx) const {
    if (relativeTo_ && !ctx.vehicleDefined(*relativeTo_)) {
        ctx.warn(
            fmt::format("{} follows vehicle '{}', which no route file or story defines", typeName(), *relativeTo_));
    }
}

}  // namespace sbsim::storyboard
