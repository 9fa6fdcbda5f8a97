#include "sbsim/storyboard/conditions/AllCondition.h"

#include <algorithm>
#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"

namespace sbsim::storyboard {

AllCondition::AllCondition(std::vector<ConditionPtr> operands) : operands_(std::move(operands)) {
    if (operands_.empty()) throw std::invalid_argument("AllCondition needs at least one condition");
    for (const ConditionPtr& c : operands_) {
        if (!c) throw std::invalid_argument("AllCondition: operand is null");
        pure_ = pure_ && c->pure();
    }
    setDepthOver("AllCondition", operands_);
}

ConditionResult AllCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    ConditionResult result = operands_.front()->test(ctx, ego);
    for (std::size_t k = 1; k < operands_.size() && result.isTrue(); ++k)
        result = ConditionResult::conjunction(result, operands_[k]->test(ctx, ego));
    return result;
}

void AllCondition::forEachChild(const std::function<void(Condition&)>& visit) const {
    for (const ConditionPtr& c : operands_) visit(*c);
}

bool AllCondition::timeOnly() const {
    return std::all_of(operands_.begin(), operands_.end(), [](const ConditionPtr& c) { return c->timeOnly(); });
}

std::optional<TimeWindow> AllCondition::timeWindow() const {
    std::optional<TimeWindow> window;
    for (const ConditionPtr& c : operands_) window = intersect(window, c->timeWindow());
    return window;
}

void AllCondition::check(CheckContext& ctx) const { ctx.warnNeverHolds(typeName(), timeWindow()); }

}  // namespace sbsim::storyboard
