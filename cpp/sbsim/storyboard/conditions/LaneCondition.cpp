#include "sbsim/storyboard/conditions/LaneCondition.h"

#include <fmt/format.h>

#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/storyboard/DescribeText.h"

namespace sbsim::storyboard {

ConditionResult LaneCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const auto listed = [this](const std::string& lane) { return ids_.contains(lane); };
    return verdicts_.passes(ctx.snapshot(), ctx.snapshot().laneKey(ego), listed);
}

void LaneCondition::prepare(const EvaluationContext& ctx) {
    verdicts_.update(ctx.snapshot(), [this](const std::string& lane) { return ids_.contains(lane); });
}

std::string LaneCondition::describe() const { return fmt::format("LaneCondition({})", describeIds(ids_)); }

void LaneCondition::check(CheckContext& ctx) const {
    ctx.warnUnknown(typeName(), NetworkObject::Lane, {ids_.begin(), ids_.end()});
}

}  // namespace sbsim::storyboard
