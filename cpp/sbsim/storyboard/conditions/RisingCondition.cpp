#include "sbsim/storyboard/conditions/RisingCondition.h"

#include <array>
#include <stdexcept>

namespace sbsim::storyboard {

RisingCondition::RisingCondition(ConditionPtr operand) : operand_(std::move(operand)) {
    if (!operand_) throw std::invalid_argument("RisingCondition: operand is null");
    setDepthOver("RisingCondition", std::array{operand_});
}

ConditionResult RisingCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    runs_.step(ctx.now());
    ConditionResult result = operand_->test(ctx, ego);
    const auto since = runs_.record(ctx.snapshot().ids()[ego], result.isTrue());
    if (!since || *since != ctx.now()) return false;
    return result;
}

}  // namespace sbsim::storyboard
