#pragma once

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Caps the vehicle's max speed (m/s) while the story is active; with `over` > 0 s a faster
/// vehicle reaches the cap gradually, by SUMO's slowDown over that time (rain, not a wall).
class SpeedEffect : public Effect {
public:
    /// Throws std::invalid_argument for a negative or non-finite speed or time.
    explicit SpeedEffect(double mps, double over = 0);
    std::string describe() const override;
    std::optional<std::string> domain() const override { return "speed"; }
    double speed() const { return mps_; }
    double over() const { return over_; }
    void apply(EffectScope& scope) override { scope.stack().pushSpeedCap(scope.token(), mps_, over_); }
    void remove(EffectScope& scope) override { scope.stack().remove(scope.token()); }

private:
    double mps_;
    double over_;  ///< s
};

}  // namespace sbsim::storyboard
