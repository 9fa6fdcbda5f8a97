#pragma once

#include <string>
#include <vector>

#include "sbsim/storyboard/WorldEffect.h"

namespace sbsim::storyboard {

/// Holds a traffic light at a signal state (SUMO's letters, one per controlled link) while the
/// story is active; then its programme resumes at the phase it was in when the hold began.
/// Overlapping holds of one light compose: the latest activated rules.
/// With `links`, `state` is one letter for those links; the light's other links keep the letters
/// they show at activation (SUMO holds a light's whole state: its programme stops for all).
/// With `keep`, the hold outlasts the story (OpenSCENARIO's TrafficSignalStateAction: the light
/// stays so until another hold of it, activated later, rules).
class TrafficLightEffect : public WorldEffect {
public:
    /// Throws std::invalid_argument for an empty id, a state that is empty or has a letter SUMO
    /// does not know (GgrsuyYoO), more than one letter for links, or a negative link.
    TrafficLightEffect(std::string tls, std::string state, std::vector<int> links = {}, bool keep = false);
    std::string describe() const override;
    /// Warns about a traffic light the network does not have.
    void check(CheckContext& ctx) const override;
    const std::string& tls() const { return tls_; }
    const std::string& state() const { return state_; }
    const std::vector<int>& links() const { return links_; }
    bool keep() const { return keep_; }
    /// An unknown light, a state of the wrong length or a link the light lacks fails here (the
    /// network is known only now).
    void apply(WorldScope& scope) override;
    void remove(WorldScope& scope) override {
        if (!keep_) scope.stack().remove(scope.token());
    }

private:
    std::string tls_;
    std::string state_;
    std::vector<int> links_;
    bool keep_;
};

}  // namespace sbsim::storyboard
