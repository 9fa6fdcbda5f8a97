#include "sbsim/storyboard/conditions/AnyCondition.h"

#include <algorithm>
#include <stdexcept>

namespace sbsim::storyboard {

AnyCondition::AnyCondition(std::vector<ConditionPtr> operands) : operands_(std::move(operands)) {
    if (operands_.empty()) throw std::invalid_argument("AnyCondition needs at least one condition");
    for (const ConditionPtr& c : operands_) {
        if (!c) throw std::invalid_argument("AnyCondition: operand is null");
        pure_ = pure_ && c->pure();
    }
    setDepthOver("AnyCondition", operands_);
}

ConditionResult AnyCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    ConditionResult result = operands_.front()->test(ctx, ego);
    for (std::size_t k = 1; k < operands_.size() && !result.isTrue(); ++k)
        result = ConditionResult::disjunction(result, operands_[k]->test(ctx, ego));
    return result;
}

void AnyCondition::forEachChild(const std::function<void(Condition&)>& visit) const {
    for (const ConditionPtr& c : operands_) visit(*c);
}

bool AnyCondition::timeOnly() const {
    return std::all_of(operands_.begin(), operands_.end(), [](const ConditionPtr& c) { return c->timeOnly(); });
}

}  // namespace sbsim::storyboard
