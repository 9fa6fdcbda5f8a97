#pragma once

#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// a ∨ b. b is evaluated only when a is false; a true a is the result as it is (its set, if any).
/// Otherwise the result is ConditionResult::disjunction(a, b), which amounts to b.
class OrCondition : public Condition {
public:
    /// Throws std::invalid_argument for a null operand.
    OrCondition(ConditionPtr a, ConditionPtr b);

    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void forEachChild(const std::function<void(Condition&)>& visit) const override;
    bool timeOnly() const override { return a_->timeOnly() && b_->timeOnly(); }

    const ConditionPtr& left() const { return a_; }
    const ConditionPtr& right() const { return b_; }

    bool pure() const override { return a_->pure() && b_->pure(); }

private:
    ConditionPtr a_;
    ConditionPtr b_;
};

}  // namespace sbsim::storyboard
