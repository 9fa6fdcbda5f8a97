#pragma once

#include <string>

#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// True for a vehicle that carries V2X equipment: the run's --penetration draw for its id, the
/// same vehicles the services file's <equipped> filter gives services (everyone at the default
/// penetration 1). A hash of the id and the seed: no state, no snapshot values, so it runs on the pool.
class EquippedCondition : public Condition {
public:
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    traffic::SnapshotColumns columns() const override { return {}; }
    bool pure() const override { return true; }
    std::string describe() const override { return "EquippedCondition()"; }
};

}  // namespace sbsim::storyboard
