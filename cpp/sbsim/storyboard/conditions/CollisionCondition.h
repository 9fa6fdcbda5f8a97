#pragma once

#include <utility>
#include <vector>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/SnapshotStamp.h"

namespace sbsim::storyboard {

/// Yields the other parties of the collisions SUMO reported for this step in which the ego took
/// part (as collider or victim). The collisions are asked of SUMO once per step, in prepare(), and
/// only when a story uses this condition; test() only reads, so the condition is pure.
class CollisionCondition : public Condition {
public:
    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void prepare(const EvaluationContext& ctx) override;
    bool pure() const override { return true; }

private:
    SnapshotStamp stamp_;
    std::vector<std::pair<VehicleIndex, VehicleIndex>> parties_;  // (ego, other), sorted, unique
};

}  // namespace sbsim::storyboard
