#pragma once

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Caps the vehicle's max speed (m/s) while the story is active.
class SpeedEffect : public Effect {
public:
    /// Throws std::invalid_argument for a negative or non-finite speed.
    explicit SpeedEffect(double mps);
    std::string describe() const override;
    std::optional<std::string> domain() const override { return "speed"; }
    double speed() const { return mps_; }
    void apply(EffectScope& scope) override { scope.stack().pushSpeedCap(scope.token(), mps_); }
    void remove(EffectScope& scope) override { scope.stack().remove(scope.token()); }

private:
    double mps_;
};

}  // namespace sbsim::storyboard
