#include "sbsim/storyboard/effects/SpeedChangeEffect.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"

namespace sbsim::storyboard {

namespace {

void requireTransition(const traffic::Transition& dynamics, std::string_view who) {
    if (!std::isfinite(dynamics.value) || dynamics.value < 0) {
        throw std::invalid_argument(fmt::format("{} needs a transition value >= 0, got {:f}", who, dynamics.value));
    }
    if (dynamics.shape != traffic::Transition::Shape::Step && dynamics.value == 0 &&
        dynamics.dimension == traffic::Transition::Dimension::Rate) {
        throw std::invalid_argument(fmt::format("{} needs a rate > 0", who));
    }
}

}  // namespace

SpeedChangeEffect::SpeedChangeEffect(double target, traffic::Transition dynamics, std::optional<std::string> relativeTo,
                                     traffic::SpeedTarget::Kind kind, bool continuous, bool safeGap, bool keep)
    : target_(target),
      dynamics_(dynamics),
      relativeTo_(std::move(relativeTo)),
      kind_(relativeTo_ ? kind : traffic::SpeedTarget::Kind::Absolute),
      continuous_(continuous && relativeTo_.has_value()),
      safeGap_(safeGap),
      keep_(keep) {
    if (!std::isfinite(target)) throw std::invalid_argument("SpeedChangeEffect needs a finite target");
    if (kind_ == traffic::SpeedTarget::Kind::Absolute && target < 0) {
        throw std::invalid_argument(fmt::format("SpeedChangeEffect needs a speed >= 0 in m/s, got {:f}", target));
    }
    if (kind_ == traffic::SpeedTarget::Kind::Factor && target < 0) {
        throw std::invalid_argument(fmt::format("SpeedChangeEffect needs a factor >= 0, got {:f}", target));
    }
    if (relativeTo_ && relativeTo_->empty()) {
        throw std::invalid_argument("SpeedChangeEffect relative_to needs a vehicle id");
    }
    if (kind_ == traffic::SpeedTarget::Kind::Absolute && kind != traffic::SpeedTarget::Kind::Absolute &&
        kind != traffic::SpeedTarget::Kind::Delta) {
        throw std::invalid_argument("SpeedChangeEffect: a factor needs relative_to, the vehicle it is of");
    }
    requireTransition(dynamics_, "SpeedChangeEffect");
}

void SpeedChangeEffect::apply(EffectScope& scope) {
    traffic::SpeedTarget target{kind_, target_, {}, continuous_};
    if (relativeTo_) {
        std::shared_ptr<traffic::VehicleController> other = scope.controllerOf(*relativeTo_);
        target.reference = [other]() -> std::optional<double> {
            try {
                return other->speed();
            } catch (const std::exception&) {
                return std::nullopt;  // not running (yet, or any more)
            }
        };
    }
    traffic::SpeedTransition transition(dynamics_, std::move(target), safeGap_);
    active_[scope.token()] = transition.outcome();
    scope.stack().pushSpeedTransition(scope.token(), std::move(transition));
}

void SpeedChangeEffect::remove(EffectScope& scope) {
    scope.stack().remove(scope.token());
    const auto it = active_.find(scope.token());
    if (it == active_.end()) return;
    if (keep_ && it->second->reached) scope.vehicle().setSpeed(it->second->target);
    active_.erase(it);
}

bool SpeedChangeEffect::complete() const {
    if (continuous_) return false;  // it follows its reference until stopped
    return std::all_of(active_.begin(), active_.end(), [](const auto& a) { return a.second->reached; });
}

std::string SpeedChangeEffect::describe() const {
    std::string target;
    switch (kind_) {
        case traffic::SpeedTarget::Kind::Absolute:
            target = fmt::format("{:g} m/s", target_);
            break;
        case traffic::SpeedTarget::Kind::Delta:
            target = fmt::format("{}'s speed {:+g} m/s", *relativeTo_, target_);
            break;
        case traffic::SpeedTarget::Kind::Factor:
            target = fmt::format("{}'s speed x {:g}", *relativeTo_, target_);
            break;
    }
    return fmt::format("SpeedChangeEffect({}{}, {}{}{})", target, continuous_ ? ", continuous" : "",
                       dynamics_.describe("m/s²"), safeGap_ ? ", safe gap" : "", keep_ ? ", kept" : "");
}

void SpeedChangeEffect::check(CheckContext& ctx) const {
    if (relativeTo_ && !ctx.vehicleDefined(*relativeTo_)) {
        ctx.warn(
            fmt::format("{} follows vehicle '{}', which no route file or story defines", typeName(), *relativeTo_));
    }
}

}  // namespace sbsim::storyboard
