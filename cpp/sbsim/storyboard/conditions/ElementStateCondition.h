#pragma once

#include <cstddef>
#include <memory>
#include <optional>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/ScenarioMachine.h"

namespace sbsim::storyboard {

/// OpenSCENARIO's StoryboardElementStateCondition: an element of a ScenarioMachine is in a state
/// (standbyState, runningState, completeState) or made a transition at this step (startTransition,
/// endTransition, stopTransition, skipTransition; completeState is also reached by end or stop). It
/// reads the machine as it stands while it advances: elements earlier in the storyboard already
/// at this step, later ones as of the step before.
class ElementStateCondition : public Condition {
public:
    /// `state` or `transition`: exactly one. Throws std::invalid_argument otherwise, for a null
    /// machine or an element it does not have.
    ElementStateCondition(std::shared_ptr<ScenarioMachine> machine, std::size_t element,
                          std::optional<ScenarioMachine::State> state,
                          std::optional<ScenarioMachine::Transition> transition);

    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    traffic::SnapshotColumns columns() const override { return {}; }
    bool timeOnly() const override { return true; }
    std::string describe() const override;

private:
    std::weak_ptr<ScenarioMachine> machine_;  // the machine holds this condition in a trigger
    std::size_t element_;
    std::optional<ScenarioMachine::State> state_;
    std::optional<ScenarioMachine::Transition> transition_;
    std::string elementName_;
};

}  // namespace sbsim::storyboard
