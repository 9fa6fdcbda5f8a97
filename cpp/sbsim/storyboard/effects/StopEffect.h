#pragma once

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Holds the vehicle at speed 0 (SUMO's setSpeed) while the story is active.
class StopEffect : public Effect {
public:
    std::optional<std::string> domain() const override { return "speed"; }
    void apply(EffectScope& scope) override { scope.stack().pushHold(scope.token(), traffic::EffectStack::Hold::Stop); }
    void remove(EffectScope& scope) override { scope.stack().remove(scope.token()); }
};

}  // namespace sbsim::storyboard
