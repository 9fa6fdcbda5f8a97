#pragma once

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Sets the vehicle's speed factor (SUMO's setSpeedFactor: the driver keeps `factor` times the
/// speed limit) while the story is active: rain, fog.
class SpeedFactorEffect : public Effect {
public:
    /// Throws std::invalid_argument for a factor that is not finite and > 0.
    explicit SpeedFactorEffect(double factor);
    std::string describe() const override;
    std::optional<std::string> domain() const override { return "speed factor"; }
    double factor() const { return factor_; }
    void apply(EffectScope& scope) override { scope.stack().pushSpeedFactor(scope.token(), factor_); }
    void remove(EffectScope& scope) override { scope.stack().remove(scope.token()); }

private:
    double factor_;
};

}  // namespace sbsim::storyboard
