#pragma once

#include <string_view>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/VehicleIdMap.h"

namespace sbsim::storyboard {

/// Once the operand was true for a vehicle, true for that vehicle from then on, until it leaves
/// the simulation ("the car crashed here", though a stopped vehicle then slides out of the area).
/// The operand is still evaluated at every step (conditions under it keep their own state as
/// they would without the latch); while it is true this yields its result (its set), after it
/// turned false a plain true.
class LatchCondition : public Condition {
public:
    /// Throws std::invalid_argument for a null operand.
    explicit LatchCondition(ConditionPtr operand);

    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void forget(std::string_view vehicleId) override;
    std::size_t heldVehicles() const override { return latched_.size(); }
    void forEachChild(const std::function<void(Condition&)>& visit) const override { visit(*operand_); }
    bool timeOnly() const override { return operand_->timeOnly(); }

    const ConditionPtr& operand() const { return operand_; }

private:
    ConditionPtr operand_;
    VehicleIdSet latched_;  ///< the vehicles the operand was true for once
};

}  // namespace sbsim::storyboard
