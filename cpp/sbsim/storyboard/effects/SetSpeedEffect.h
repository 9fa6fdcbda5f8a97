#pragma once

#include "sbsim/storyboard/Effect.h"

namespace sbsim::storyboard {

/// Once, at activation: the vehicle drives at `mps` from then on (SUMO's setSpeed, within its
/// safety checks), as an OpenSCENARIO entity keeps the target of its last step SpeedAction.
/// Deactivation does nothing: the speed stays until another command sets one.
class SetSpeedEffect : public Effect {
public:
    /// Throws std::invalid_argument for a negative or non-finite speed.
    explicit SetSpeedEffect(double mps);
    std::string describe() const override;
    double speed() const { return mps_; }
    void apply(EffectScope& scope) override { scope.vehicle().setSpeed(mps_); }
    void remove(EffectScope& /*scope*/) override {}

private:
    double mps_;
};

}  // namespace sbsim::storyboard
