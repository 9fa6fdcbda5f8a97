#pragma once

#include <vector>

#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// c1 ∨ c2 ∨ … ∨ cn, evaluated left to right and stopping at the first true operand (whose result,
/// a set if it is one, is the result), exactly as nested OrConditions would. Sets combine by
/// ConditionResult::disjunction.
class AnyCondition : public Condition {
public:
    /// Throws std::invalid_argument for no operands or a null one.
    explicit AnyCondition(std::vector<ConditionPtr> operands);

    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void forEachChild(const std::function<void(Condition&)>& visit) const override;
    bool timeOnly() const override;
    bool pure() const override { return pure_; }

    const std::vector<ConditionPtr>& operands() const { return operands_; }

private:
    std::vector<ConditionPtr> operands_;
    bool pure_ = true;
};

}  // namespace sbsim::storyboard
