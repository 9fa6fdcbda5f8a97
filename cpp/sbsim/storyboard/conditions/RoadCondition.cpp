#include "sbsim/storyboard/conditions/RoadCondition.h"

namespace sbsim::storyboard {

ConditionResult RoadCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const auto listed = [this](const std::string& road) { return ids_.contains(road); };
    return verdicts_.passes(ctx.snapshot(), ctx.snapshot().roadKey(ego), listed);
}

void RoadCondition::prepare(const EvaluationContext& ctx) {
    verdicts_.update(ctx.snapshot(), [this](const std::string& road) { return ids_.contains(road); });
}

}  // namespace sbsim::storyboard
