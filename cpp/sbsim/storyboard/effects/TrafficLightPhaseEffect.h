#pragma once

#include <string>

#include "sbsim/storyboard/WorldEffect.h"

namespace sbsim::storyboard {

/// Switches a traffic light's programme to one of its phases when the story activates (SUMO's
/// setPhase: the phase's full duration, then the programme goes on); every hold of the light ends
/// (NetworkStack::switchPhase). Ending the story changes nothing. OpenSCENARIO's
/// TrafficSignalControllerAction on a SUMO traffic light.
class TrafficLightPhaseEffect : public WorldEffect {
public:
    /// Throws std::invalid_argument for an empty id or a negative phase.
    TrafficLightPhaseEffect(std::string tls, int phase);
    std::string describe() const override;
    /// Warns about a traffic light the network does not have.
    void check(CheckContext& ctx) const override;
    const std::string& tls() const { return tls_; }
    int phase() const { return phase_; }
    /// An unknown light, or a phase its programme lacks (SUMO's error), fails here.
    void apply(WorldScope& scope) override { scope.stack().switchPhase(tls_, phase_); }
    void remove(WorldScope& /*scope*/) override {}

private:
    std::string tls_;
    int phase_;
};

}  // namespace sbsim::storyboard
