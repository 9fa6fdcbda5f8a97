#include "sbsim/storyboard/conditions/TriggeringEntitiesCondition.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <stdexcept>

namespace sbsim::storyboard {

TriggeringEntitiesCondition::TriggeringEntitiesCondition(std::vector<std::shared_ptr<EntityCondition>> entities,
                                                         bool all)
    : entities_(std::move(entities)), all_(all) {
    if (entities_.empty()) throw std::invalid_argument("TriggeringEntitiesCondition needs at least one entity");
    std::vector<ConditionPtr> children;
    for (const auto& e : entities_) {
        if (!e) throw std::invalid_argument("TriggeringEntitiesCondition: an entity's condition is null");
        children.push_back(e);
    }
    setDepthOver("TriggeringEntitiesCondition", children);
}

ConditionResult TriggeringEntitiesCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    std::vector<VehicleIndex> holds;
    for (const auto& e : entities_) {
        if (!e->test(ctx, ego).isTrue()) continue;
        if (const auto index = ctx.snapshot().indexOf(e->vehicleId())) holds.push_back(*index);
    }
    if (all_ && holds.size() != entities_.size()) return false;
    std::sort(holds.begin(), holds.end());
    holds.erase(std::unique(holds.begin(), holds.end()), holds.end());
    return ConditionResult::ofOthers(std::move(holds));
}

std::string TriggeringEntitiesCondition::describe() const {
    std::vector<std::string> ids;
    for (const auto& e : entities_) ids.push_back(e->vehicleId());
    return fmt::format("TriggeringEntitiesCondition({} of {})", all_ ? "all" : "any", fmt::join(ids, ", "));
}

}  // namespace sbsim::storyboard
