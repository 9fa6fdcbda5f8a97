#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "sbsim/storyboard/Effect.h"
#include "sbsim/storyboard/effects/ReachedFlags.h"
#include "sbsim/traffic/EffectStack.h"
#include "sbsim/traffic/Transition.h"

namespace sbsim::storyboard {

/// Moves the vehicle `offset` m (positive to the left) off the centre of the lane it is on at
/// activation, along a transition (OpenSCENARIO's LaneOffsetAction: its shape with a time, or with
/// its maxLateralAcc), each step through SUMO's sublane model, and holds that offset while the story
/// is active (SUMO's own lane changes are off meanwhile); then SUMO aligns the vehicle again.
class LaneOffsetEffect : public Effect {
public:
    /// Throws std::invalid_argument for a non-finite offset, a bad transition or a max lateral
    /// acceleration <= 0.
    LaneOffsetEffect(double offset, traffic::Transition dynamics, std::optional<double> maxLateralAcceleration);
    std::string describe() const override;
    std::optional<std::string> domain() const override { return "lane"; }
    void apply(EffectScope& scope) override;
    void remove(EffectScope& scope) override {
        scope.stack().remove(scope.token());
        reached_.forget(scope.token());
    }
    /// Once the manoeuvre reached its target on every vehicle it acts on.
    bool complete() const override { return reached_.allReached(); }

    double offset() const { return offset_; }
    const traffic::Transition& dynamics() const { return dynamics_; }
    const std::optional<double>& maxLateralAcceleration() const { return maxLateralAcceleration_; }

private:
    double offset_;
    traffic::Transition dynamics_;
    std::optional<double> maxLateralAcceleration_;  ///< m/s²
    ReachedFlags reached_;
};

}  // namespace sbsim::storyboard
