#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "sbsim/storyboard/Effect.h"
#include "sbsim/traffic/EffectStack.h"
#include "sbsim/traffic/SpeedTransition.h"
#include "sbsim/traffic/Transition.h"

namespace sbsim::storyboard {

/// Takes the vehicle from its speed at activation to a target speed along a transition
/// (OpenSCENARIO's SpeedAction: AbsoluteTargetSpeed or RelativeTargetSpeed, with its
/// TransitionDynamics), commanded each step, and holds the target after while the story is active;
/// then SUMO has the speed again. The target is `target` m/s, or relative to vehicle
/// `relativeTo`'s speed: that plus `target` m/s (Delta) or times `target` (Factor), read at
/// activation or, `continuous`, every step. The shape is exact (SUMO's acceleration bounds and
/// safe speed off, its speed limit disregarded) unless `safeGap`: then SUMO keeps the safe gap to
/// the leader, which also bounds the change to the vehicle's acceleration and deceleration.
/// complete() once the change ran on every vehicle it acts on (a continuous target: never, as
/// OpenSCENARIO's); `keep`: a vehicle whose change ran keeps the target after the story ends (SUMO's
/// setSpeed once more, within its safety checks, as SetSpeedEffect), as an OpenSCENARIO entity does.
class SpeedChangeEffect : public Effect {
public:
    /// Throws std::invalid_argument for a negative absolute speed or factor, a negative or
    /// non-finite transition value, or an empty reference id.
    SpeedChangeEffect(double target, traffic::Transition dynamics, std::optional<std::string> relativeTo = std::nullopt,
                      traffic::SpeedTarget::Kind kind = traffic::SpeedTarget::Kind::Delta, bool continuous = false,
                      bool safeGap = false, bool keep = false);
    std::string describe() const override;
    std::optional<std::string> domain() const override { return "speed"; }
    void apply(EffectScope& scope) override;
    void remove(EffectScope& scope) override;
    void check(CheckContext& ctx) const override;
    bool complete() const override;
    void vehicleLeft(traffic::EffectStack::Token token) override { active_.erase(token); }

    double target() const { return target_; }
    const traffic::Transition& dynamics() const { return dynamics_; }
    const std::optional<std::string>& relativeTo() const { return relativeTo_; }
    /// Absolute without a reference vehicle, else Delta or Factor.
    traffic::SpeedTarget::Kind kind() const { return kind_; }
    bool continuous() const { return continuous_; }
    bool safeGap() const { return safeGap_; }
    bool keep() const { return keep_; }

private:
    double target_;
    traffic::Transition dynamics_;
    std::optional<std::string> relativeTo_;
    traffic::SpeedTarget::Kind kind_;
    bool continuous_;
    bool safeGap_;
    bool keep_;
    std::map<traffic::EffectStack::Token, std::shared_ptr<const traffic::SpeedTransition::Outcome>>
        active_;  ///< per activation
};

}  // namespace sbsim::storyboard
