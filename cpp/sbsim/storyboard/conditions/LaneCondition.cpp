#include "sbsim/storyboard/conditions/LaneCondition.h"

namespace sbsim::storyboard {

ConditionResult LaneCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const auto listed = [this](const std::string& lane) { return ids_.contains(lane); };
    return verdicts_.passes(ctx.snapshot(), ctx.snapshot().laneKey(ego), listed);
}

void LaneCondition::prepare(const EvaluationContext& ctx) {
    verdicts_.update(ctx.snapshot(), [this](const std::string& lane) { return ids_.contains(lane); });
}

}  // namespace sbsim::storyboard
