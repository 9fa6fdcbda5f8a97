#include "sbsim/storyboard/conditions/CarSetCondition.h"

namespace sbsim::storyboard {

CarSetCondition::CarSetCondition(std::set<std::string> ids) : ids_(std::move(ids)), lookup_(ids_.begin(), ids_.end()) {}

ConditionResult CarSetCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    return lookup_.contains(ctx.snapshot().ids()[ego]);
}

}  // namespace sbsim::storyboard
