#pragma once

#include <vector>

#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// c1 ∧ c2 ∧ … ∧ cn, evaluated left to right and stopping at the first false operand, exactly as
/// nested AndConditions would (so stateful operands see only the vehicles that passed the ones
/// before them). Sets combine by ConditionResult::conjunction.
class AllCondition : public Condition {
public:
    /// Throws std::invalid_argument for no operands or a null one.
    explicit AllCondition(std::vector<ConditionPtr> operands);

    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void forEachChild(const std::function<void(Condition&)>& visit) const override;
    bool timeOnly() const override;
    std::optional<TimeWindow> timeWindow() const override;
    /// Warns when its operands' time windows do not overlap.
    void check(CheckContext& ctx) const override;
    bool pure() const override { return pure_; }

    const std::vector<ConditionPtr>& operands() const { return operands_; }

private:
    std::vector<ConditionPtr> operands_;
    bool pure_ = true;
};

}  // namespace sbsim::storyboard
