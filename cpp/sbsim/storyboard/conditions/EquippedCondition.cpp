#include "sbsim/storyboard/conditions/EquippedCondition.h"

namespace sbsim::storyboard {

ConditionResult EquippedCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    return ConditionResult(ctx.equipped(ctx.snapshot().ids()[ego]));
}

}  // namespace sbsim::storyboard
