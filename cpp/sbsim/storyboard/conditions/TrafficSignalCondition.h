#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// OpenSCENARIO's TrafficSignalCondition on a SUMO traffic light: true while the light shows a
/// state. Either the whole light (`links` empty: `state` has one SUMO letter per controlled link)
/// or some of its links (`state` is one letter, which each of them shows). Letters compare by
/// colour, case aside: 'G' and 'g' are both green, 'Y'/'y' yellow, 'O'/'o' off ('r' red, 'u'
/// red-yellow, 's' stop then go). Depends on no vehicle: the light's state is asked of SUMO once
/// per step, in prepare() (EvaluationContext::queries), and test() only reads it, so a WorldStory
/// and an OpenSCENARIO trigger take it and it is pure. It sees the state SUMO switched its lights
/// to for this step, and a story's TrafficLightEffect from the step after the story acted.
class TrafficSignalCondition : public Condition {
public:
    /// Throws std::invalid_argument for an empty id, a state with a letter SUMO does not know
    /// (GgrsuyYoO), more than one letter for links, or a negative link.
    TrafficSignalCondition(std::string tls, std::string state, std::vector<int> links = {});

    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void prepare(const EvaluationContext& ctx) override;
    traffic::SnapshotColumns columns() const override { return {}; }
    bool pure() const override { return true; }
    bool timeOnly() const override { return true; }
    std::string describe() const override;
    /// Warns about a traffic light the network does not have.
    void check(CheckContext& ctx) const override;

    const std::string& tls() const { return tls_; }
    const std::string& state() const { return state_; }
    const std::vector<int>& links() const { return links_; }

private:
    /// Whether SUMO's state `now` shows what this condition asks; throws std::invalid_argument
    /// (naming the light) when it has fewer links than the condition names.
    bool shows(const std::string& now) const;

    std::string tls_;
    std::string state_;
    std::vector<int> links_;
    std::optional<kernel::SimTime> readAt_;  // the step `holds_` was read for
    bool holds_ = false;
};

}  // namespace sbsim::storyboard
