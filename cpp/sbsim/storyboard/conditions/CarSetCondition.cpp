#include "sbsim/storyboard/conditions/CarSetCondition.h"

#include <fmt/format.h>

#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/storyboard/DescribeText.h"

namespace sbsim::storyboard {

CarSetCondition::CarSetCondition(std::set<std::string> ids) : ids_(std::move(ids)), lookup_(ids_.begin(), ids_.end()) {}

ConditionResult CarSetCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    return lookup_.contains(ctx.snapshot().ids()[ego]);
}

std::string CarSetCondition::describe() const { return fmt::format("CarSetCondition({})", describeIds(ids_)); }

void CarSetCondition::check(CheckContext& ctx) const {
    std::set<std::string> unknown;
    for (const std::string& id : ids_) {
        if (!ctx.vehicleDefined(id)) unknown.insert(id);
    }
    if (!unknown.empty())
        ctx.warn(fmt::format("CarSetCondition names vehicles no route file defines: {}", describeIds(unknown)));
}

}  // namespace sbsim::storyboard
