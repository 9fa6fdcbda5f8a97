#pragma once

#include <memory>
#include <vector>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/EntityCondition.h"

namespace sbsim::storyboard {

/// OpenSCENARIO's ByEntityCondition: one condition per triggering entity (each an EntityCondition),
/// true when it holds for any of them (`all`: for every one). Every entity's condition is evaluated
/// each time (no short-circuit, so each keeps its own edges and state); the result's others are the
/// entities it holds for — the triggering entities a ManeuverGroup with selectTriggeringEntities
/// takes as its actors (ScenarioMachine). Time-only: it does not depend on the ego.
class TriggeringEntitiesCondition : public Condition {
public:
    /// Throws std::invalid_argument for no entity or a null one.
    TriggeringEntitiesCondition(std::vector<std::shared_ptr<EntityCondition>> entities, bool all);

    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    traffic::SnapshotColumns columns() const override { return {}; }
    bool timeOnly() const override { return true; }
    void forEachChild(const std::function<void(Condition&)>& visit) const override {
        for (const auto& e : entities_) visit(*e);
    }
    std::string describe() const override;

    const std::vector<std::shared_ptr<EntityCondition>>& entities() const { return entities_; }
    bool all() const { return all_; }

private:
    std::vector<std::shared_ptr<EntityCondition>> entities_;
    bool all_;
};

}  // namespace sbsim::storyboard
