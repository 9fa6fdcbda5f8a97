#include "sbsim/storyboard/conditions/ElementStateCondition.h"

#include <fmt/format.h>

#include <stdexcept>

namespace sbsim::storyboard {

ElementStateCondition::ElementStateCondition(std::shared_ptr<ScenarioMachine> machine, std::size_t element,
                                             std::optional<ScenarioMachine::State> state,
                                             std::optional<ScenarioMachine::Transition> transition)
    : machine_(machine), element_(element), state_(state), transition_(transition) {
    if (!machine) throw std::invalid_argument("ElementStateCondition: the machine is null");
    if (element >= machine->size()) {
        throw std::invalid_argument(fmt::format("ElementStateCondition: the machine has no element {}", element));
    }
    if (state.has_value() == transition.has_value() || transition == ScenarioMachine::Transition::none) {
        throw std::invalid_argument("ElementStateCondition: give a state or a transition");
    }
    elementName_ = machine->name(element);
}

ConditionResult ElementStateCondition::test(const EvaluationContext& ctx, VehicleIndex /*ego*/) {
    const std::shared_ptr<ScenarioMachine> m = machine_.lock();
    if (!m) return false;
    if (state_) return m->state(element_) == *state_;
    return m->transitionedAt(element_, *transition_, ctx.now());
}

std::string ElementStateCondition::describe() const {
    return fmt::format("ElementStateCondition('{}', {})", elementName_,
                       state_ ? ScenarioMachine::stateName(*state_) : ScenarioMachine::transitionName(*transition_));
}

}  // namespace sbsim::storyboard
