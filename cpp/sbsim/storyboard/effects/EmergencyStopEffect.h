#pragma once

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Brakes with the vehicle's emergency deceleration, ignoring its safe-speed checks, while active.
class EmergencyStopEffect : public Effect {
public:
    std::optional<std::string> domain() const override { return "speed"; }
    void apply(EffectScope& scope) override {
        scope.stack().pushHold(scope.token(), traffic::EffectStack::Hold::EmergencyStop);
    }
    void remove(EffectScope& scope) override { scope.stack().remove(scope.token()); }
};

}  // namespace sbsim::storyboard
