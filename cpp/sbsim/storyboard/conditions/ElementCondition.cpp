#include "sbsim/storyboard/conditions/ElementCondition.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/storyboard/DescribeText.h"

namespace sbsim::storyboard {

ElementCondition::ElementCondition(std::shared_ptr<ScenarioMachine> machine, std::size_t element,
                                   std::set<std::string> actors)
    : machine_(std::move(machine)),
      element_(element),
      actors_(std::move(actors)),
      lookup_(actors_.begin(), actors_.end()),
      selects_(false) {
    if (!machine_) throw std::invalid_argument("ElementCondition: the machine is null");
    if (element_ >= machine_->size()) {
        throw std::invalid_argument(fmt::format("ElementCondition: the machine has no element {}", element_));
    }
    selects_ = machine_->selectsTriggeringEntities(element_);
}

ConditionResult ElementCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    machine_->advance(ctx);
    if (machine_->state(element_) != ScenarioMachine::State::running) return false;
    if (actors_.empty() && !selects_) return true;
    const std::string& id = ctx.snapshot().ids()[ego];
    if (lookup_.contains(id)) return true;
    if (!selects_) return false;
    const std::vector<std::string>& selected = machine_->selectedActors(element_);
    return std::binary_search(selected.begin(), selected.end(), id);
}

std::string ElementCondition::describe() const {
    std::string s = fmt::format("ElementCondition({} '{}'", ScenarioMachine::kindName(machine_->kind(element_)),
                                machine_->name(element_));
    if (!actors_.empty()) s += fmt::format(", actors {}", describeIds(actors_));
    if (selects_)
        s += actors_.empty() ? ", actors: the entities that triggered its act"
                             : " and the entities that triggered its act";
    const std::string triggers = machine_->describeTriggers(element_);
    if (!triggers.empty()) s += "; " + triggers;
    return s + ")";
}

void ElementCondition::check(CheckContext& ctx) const {
    std::set<std::string> unknown;
    for (const std::string& id : actors_) {
        if (!ctx.vehicleDefined(id)) unknown.insert(id);
    }
    if (!unknown.empty())
        ctx.warn(fmt::format("ElementCondition names actors no route file defines: {}", describeIds(unknown)));
}

}  // namespace sbsim::storyboard
