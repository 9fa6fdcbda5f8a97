#include "sbsim/storyboard/conditions/HoldCondition.h"

#include <fmt/format.h>

#include <array>
#include <stdexcept>

#include "sbsim/storyboard/DescribeText.h"

namespace sbsim::storyboard {

HoldCondition::HoldCondition(ConditionPtr operand, kernel::SimTime duration)
    : operand_(std::move(operand)), duration_(duration) {
    if (!operand_) throw std::invalid_argument("HoldCondition: operand is null");
    setDepthOver("HoldCondition", std::array{operand_});
    if (duration_ < kernel::SimTime::zero())
        throw std::invalid_argument("HoldCondition: duration " + duration_.str() + " s is negative");
}

ConditionResult HoldCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    runs_.step(ctx.now());
    ConditionResult result = operand_->test(ctx, ego);
    const auto since = runs_.record(ctx.snapshot().ids()[ego], result.isTrue());
    if (!since || ctx.now() - *since < duration_) return false;
    return result;
}

std::string HoldCondition::describe() const { return fmt::format("HoldCondition({})", describeTime(duration_)); }

}  // namespace sbsim::storyboard
