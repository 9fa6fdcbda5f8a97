#pragma once

#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// a ∧ b. b is evaluated only when a is true, so stateful conditions on the right (Limit,
/// Likelihood, Deferring) see only the vehicles that passed the left side, as a story author
/// writing `a & limit` expects. Sets combine by ConditionResult::conjunction.
class AndCondition : public Condition {
public:
    /// Throws std::invalid_argument for a null operand.
    AndCondition(ConditionPtr a, ConditionPtr b);

    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void forEachChild(const std::function<void(Condition&)>& visit) const override;
    bool timeOnly() const override { return a_->timeOnly() && b_->timeOnly(); }
    std::optional<TimeWindow> timeWindow() const override { return intersect(a_->timeWindow(), b_->timeWindow()); }
    /// Warns when its operands' time windows do not overlap.
    void check(CheckContext& ctx) const override;

    const ConditionPtr& left() const { return a_; }
    const ConditionPtr& right() const { return b_; }

    bool pure() const override { return a_->pure() && b_->pure(); }

private:
    ConditionPtr a_;
    ConditionPtr b_;
};

}  // namespace sbsim::storyboard
