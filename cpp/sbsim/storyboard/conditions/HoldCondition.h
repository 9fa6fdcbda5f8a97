#pragma once

#include <string_view>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/TrueRuns.h"

namespace sbsim::storyboard {

/// True for a vehicle once the operand has been true at every step for at least `duration`: the
/// operand's first true step counts as 0 s held, and one false step (or a step the vehicle was not
/// evaluated, see TrueRuns) starts again. While true it returns the operand's result (its set).
class HoldCondition : public Condition {
public:
    /// Throws std::invalid_argument for a null operand or a negative duration.
    HoldCondition(ConditionPtr operand, kernel::SimTime duration);

    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void prepare(const EvaluationContext& ctx) override { runs_.step(ctx.now()); }
    void forget(std::string_view vehicleId) override { runs_.forget(vehicleId); }
    std::size_t heldVehicles() const override { return runs_.size(); }
    void forEachChild(const std::function<void(Condition&)>& visit) const override { visit(*operand_); }
    bool timeOnly() const override { return operand_->timeOnly(); }

    std::string describe() const override;
    const ConditionPtr& operand() const { return operand_; }
    kernel::SimTime duration() const { return duration_; }
    /// Vehicles currently in a run of true steps (state kept).
    std::size_t tracked() const { return runs_.size(); }

private:
    ConditionPtr operand_;
    kernel::SimTime duration_;
    TrueRuns runs_;
};

}  // namespace sbsim::storyboard
