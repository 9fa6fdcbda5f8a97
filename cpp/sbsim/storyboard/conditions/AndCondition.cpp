#include "sbsim/storyboard/conditions/AndCondition.h"

#include <array>
#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"

namespace sbsim::storyboard {

AndCondition::AndCondition(ConditionPtr a, ConditionPtr b) : a_(std::move(a)), b_(std::move(b)) {
    if (!a_ || !b_) throw std::invalid_argument("AndCondition: operand is null");
    setDepthOver("AndCondition", std::array{a_, b_});
}

ConditionResult AndCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    ConditionResult left = a_->test(ctx, ego);
    if (!left) return left;
    return ConditionResult::conjunction(left, b_->test(ctx, ego));
}

void AndCondition::forEachChild(const std::function<void(Condition&)>& visit) const {
    visit(*a_);
    visit(*b_);
}

void AndCondition::check(CheckContext& ctx) const { ctx.warnNeverHolds(typeName(), timeWindow()); }

}  // namespace sbsim::storyboard
