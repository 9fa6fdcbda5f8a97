#include "sbsim/storyboard/conditions/RoadCondition.h"

#include <fmt/format.h>

#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/storyboard/DescribeText.h"

namespace sbsim::storyboard {

ConditionResult RoadCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const auto listed = [this](const std::string& road) { return ids_.contains(road); };
    return verdicts_.passes(ctx.snapshot(), ctx.snapshot().roadKey(ego), listed);
}

void RoadCondition::prepare(const EvaluationContext& ctx) {
    verdicts_.update(ctx.snapshot(), [this](const std::string& road) { return ids_.contains(road); });
}

std::string RoadCondition::describe() const { return fmt::format("RoadCondition({})", describeIds(ids_)); }

void RoadCondition::check(CheckContext& ctx) const {
    ctx.warnUnknown(typeName(), NetworkObject::Edge, {ids_.begin(), ids_.end()});
}

}  // namespace sbsim::storyboard
