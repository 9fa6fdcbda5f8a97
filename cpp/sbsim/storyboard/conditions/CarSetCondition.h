#pragma once

#include <set>
#include <string>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/VehicleIdMap.h"

namespace sbsim::storyboard {

/// True for the vehicles whose id is in the given set.
class CarSetCondition : public Condition {
public:
    explicit CarSetCondition(std::set<std::string> ids);
    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    std::string describe() const override;
    /// Warns about ids no route file (and no story) defines.
    void check(CheckContext& ctx) const override;
    const std::set<std::string>& ids() const { return ids_; }

    bool pure() const override { return true; }

private:
    std::set<std::string> ids_;
    VehicleIdSet lookup_;  // the same ids, hashed: one lookup per vehicle and step
};

}  // namespace sbsim::storyboard
