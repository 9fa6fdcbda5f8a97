#pragma once

#include <string>

#include "sbsim/storyboard/WorldEffect.h"

namespace sbsim::storyboard {

/// Holds a traffic light at a signal state (SUMO's letters, one per controlled link) while the
/// story is active; then its programme resumes at the phase it was in when the hold began.
/// Overlapping holds of one light compose: the latest activated rules.
class TrafficLightEffect : public WorldEffect {
public:
    /// Throws std::invalid_argument for an empty id, or a state that is empty or has a letter
    /// SUMO does not know (GgrsuyYoO).
    TrafficLightEffect(std::string tls, std::string state);
    std::string describe() const override;
    /// Warns about a traffic light the network does not have.
    void check(CheckContext& ctx) const override;
    const std::string& tls() const { return tls_; }
    const std::string& state() const { return state_; }
    /// An unknown light or a state of the wrong length fails here (the network is known only now).
    void apply(WorldScope& scope) override { scope.stack().pushSignalState(scope.token(), tls_, state_); }
    void remove(WorldScope& scope) override { scope.stack().remove(scope.token()); }

private:
    std::string tls_;
    std::string state_;
};

}  // namespace sbsim::storyboard
