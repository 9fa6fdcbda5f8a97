#include "sbsim/storyboard/conditions/NotCondition.h"

#include <array>
#include <stdexcept>

namespace sbsim::storyboard {

NotCondition::NotCondition(ConditionPtr operand) : operand_(std::move(operand)) {
    if (!operand_) throw std::invalid_argument("NotCondition: operand is null");
    setDepthOver("NotCondition", std::array{operand_});
}

ConditionResult NotCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    return !operand_->test(ctx, ego).isTrue();
}

}  // namespace sbsim::storyboard
