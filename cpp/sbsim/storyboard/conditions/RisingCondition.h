#pragma once

#include <string_view>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/TrueRuns.h"

namespace sbsim::storyboard {

/// True only at the step where the operand turns from false to true for a vehicle (the first step
/// a vehicle is evaluated counts as a rise if the operand is true; so does a step after one the
/// vehicle was not evaluated, see TrueRuns). At that step it returns the operand's result (its
/// set), so a story on it activates for one step.
class RisingCondition : public Condition {
public:
    /// Throws std::invalid_argument for a null operand.
    explicit RisingCondition(ConditionPtr operand);

    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void prepare(const EvaluationContext& ctx) override { runs_.step(ctx.now()); }
    void forget(std::string_view vehicleId) override { runs_.forget(vehicleId); }
    std::size_t heldVehicles() const override { return runs_.size(); }
    void forEachChild(const std::function<void(Condition&)>& visit) const override { visit(*operand_); }
    bool timeOnly() const override { return operand_->timeOnly(); }

    const ConditionPtr& operand() const { return operand_; }
    std::size_t tracked() const { return runs_.size(); }

private:
    ConditionPtr operand_;
    TrueRuns runs_;
};

}  // namespace sbsim::storyboard
