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
/// Relative (`relativeTo`, RelativeTargetLaneOffset): `offset` m off vehicle `relativeTo`'s own
/// offset from its lane's centre at activation. Continuous (OpenSCENARIO's continuous=true): the
/// offset is held until the story ends, so its event runs until stopped (complete() never).
class LaneOffsetEffect : public Effect {
public:
    /// Throws std::invalid_argument for a non-finite offset, a bad transition, a max lateral
    /// acceleration <= 0 or an empty vehicle id.
    LaneOffsetEffect(double offset, traffic::Transition dynamics, std::optional<double> maxLateralAcceleration,
                     std::optional<std::string> relativeTo = std::nullopt, bool continuous = false);
    std::string describe() const override;
    std::optional<std::string> domain() const override { return "lane"; }
    void apply(EffectScope& scope) override;
    void remove(EffectScope& scope) override {
        scope.stack().remove(scope.token());
        reached_.forget(scope.token());
    }
    /// Once the manoeuvre reached its target on every vehicle it acts on.
    bool complete() const override { return !continuous_ && reached_.allReached(); }
    void vehicleLeft(traffic::EffectStack::Token token) override { reached_.forget(token); }

    double offset() const { return offset_; }
    const traffic::Transition& dynamics() const { return dynamics_; }
    const std::optional<double>& maxLateralAcceleration() const { return maxLateralAcceleration_; }
    const std::optional<std::string>& relativeTo() const { return relativeTo_; }
    bool continuous() const { return continuous_; }
    void check(CheckContext& ctx) const override;

private:
    double offset_;
    traffic::Transition dynamics_;
    std::optional<double> maxLateralAcceleration_;  ///< m/s²
    std::optional<std::string> relativeTo_;
    bool continuous_;
    ReachedFlags reached_;
};

}  // namespace sbsim::storyboard
