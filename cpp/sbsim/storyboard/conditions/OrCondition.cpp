#include "sbsim/storyboard/conditions/OrCondition.h"

#include <array>
#include <stdexcept>

namespace sbsim::storyboard {

OrCondition::OrCondition(ConditionPtr a, ConditionPtr b) : a_(std::move(a)), b_(std::move(b)) {
    if (!a_ || !b_) throw std::invalid_argument("OrCondition: operand is null");
    setDepthOver("OrCondition", std::array{a_, b_});
}

ConditionResult OrCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    ConditionResult left = a_->test(ctx, ego);
    if (left) return left;
    return ConditionResult::disjunction(left, b_->test(ctx, ego));
}

void OrCondition::forEachChild(const std::function<void(Condition&)>& visit) const {
    visit(*a_);
    visit(*b_);
}

}  // namespace sbsim::storyboard
