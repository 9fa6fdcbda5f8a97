#pragma once

#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// True iff the operand is false (a set counts as true iff non-empty). Yields a plain bool: the
/// vehicles that made the operand true are exactly the ones this condition says are absent.
class NotCondition : public Condition {
public:
    /// Throws std::invalid_argument for a null operand.
    explicit NotCondition(ConditionPtr operand);

    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void forEachChild(const std::function<void(Condition&)>& visit) const override { visit(*operand_); }
    bool timeOnly() const override { return operand_->timeOnly(); }
    bool pure() const override { return operand_->pure(); }

    const ConditionPtr& operand() const { return operand_; }

private:
    ConditionPtr operand_;
};

}  // namespace sbsim::storyboard
