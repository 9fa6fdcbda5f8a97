#include "sbsim/storyboard/conditions/EntityCondition.h"

#include <fmt/format.h>

#include <array>
#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"

namespace sbsim::storyboard {

EntityCondition::EntityCondition(std::string vehicleId, ConditionPtr operand)
    : vehicleId_(std::move(vehicleId)), operand_(std::move(operand)) {
    if (vehicleId_.empty()) throw std::invalid_argument("EntityCondition: the vehicle id is empty");
    if (!operand_) throw std::invalid_argument("EntityCondition: operand is null");
    setDepthOver("EntityCondition", std::array{operand_});
}

ConditionResult EntityCondition::test(const EvaluationContext& ctx, VehicleIndex /*ego*/) {
    const auto index = ctx.snapshot().indexOf(vehicleId_);
    if (!index) return false;
    return operand_->test(ctx, *index);
}

std::string EntityCondition::describe() const { return fmt::format("EntityCondition({})", vehicleId_); }

void EntityCondition::check(CheckContext& ctx) const {
    if (!ctx.vehicleDefined(vehicleId_))
        ctx.warn(fmt::format("EntityCondition names a vehicle no route file defines: {}", vehicleId_));
}

}  // namespace sbsim::storyboard
