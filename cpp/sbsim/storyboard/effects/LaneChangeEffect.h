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

/// A lane change as a lateral manoeuvre along a transition (OpenSCENARIO's LaneChangeAction with
/// its LaneChangeActionDynamics and targetLaneOffset): the vehicle moves across its road from where
/// it is at activation to the centre of the target lane (plus `offset` m, positive to the left),
/// each step through SUMO's sublane model, and holds it while the story is active (SUMO's own lane
/// changes are off meanwhile); then SUMO's lane-change model decides again. The target lane is
/// `lane` (SUMO's index from the right), or `lane` lanes to the left (negative: right) of the
/// vehicle's own lane (`Relative::Self`) or of vehicle `relativeTo`'s lane at activation.
class LaneChangeEffect : public Effect {
public:
    enum class Relative { Absolute, Self, Vehicle };
    /// Throws std::invalid_argument for a negative absolute lane, a bad transition or an empty id.
    LaneChangeEffect(int lane, traffic::Transition dynamics, Relative relative = Relative::Absolute,
                     std::optional<std::string> relativeTo = std::nullopt, double offset = 0);
    std::string describe() const override;
    std::optional<std::string> domain() const override { return "lane"; }
    void apply(EffectScope& scope) override;
    void remove(EffectScope& scope) override {
        scope.stack().remove(scope.token());
        reached_.forget(scope.token());
    }
    /// Once the manoeuvre reached its target on every vehicle it acts on.
    bool complete() const override { return reached_.allReached(); }
    void vehicleLeft(traffic::EffectStack::Token token) override { reached_.forget(token); }
    void check(CheckContext& ctx) const override;

    int lane() const { return lane_; }
    const traffic::Transition& dynamics() const { return dynamics_; }
    Relative relative() const { return relative_; }
    const std::optional<std::string>& relativeTo() const { return relativeTo_; }
    double offset() const { return offset_; }

private:
    int lane_;
    traffic::Transition dynamics_;
    Relative relative_;
    std::optional<std::string> relativeTo_;
    double offset_;
    ReachedFlags reached_;
};

}  // namespace sbsim::storyboard
