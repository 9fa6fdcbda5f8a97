#include "sbsim/storyboard/conditions/LatchCondition.h"

#include <array>
#include <stdexcept>

namespace sbsim::storyboard {

LatchCondition::LatchCondition(ConditionPtr operand) : operand_(std::move(operand)) {
    if (!operand_) throw std::invalid_argument("LatchCondition: operand is null");
    setDepthOver("LatchCondition", std::array{operand_});
}

ConditionResult LatchCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    ConditionResult result = operand_->test(ctx, ego);
    const std::string_view id = ctx.snapshot().ids()[ego];
    if (result.isTrue()) {
        if (latched_.find(id) == latched_.end()) latched_.emplace(id);
        return result;
    }
    return latched_.find(id) != latched_.end();
}

void LatchCondition::forget(std::string_view vehicleId) {
    if (const auto it = latched_.find(vehicleId); it != latched_.end()) latched_.erase(it);
}

}  // namespace sbsim::storyboard
