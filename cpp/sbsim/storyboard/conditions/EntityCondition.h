#pragma once

#include <string>

#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// Asks `operand` about one named vehicle, whichever vehicle the story is evaluated for: false
/// while that vehicle is not running, else the operand's result for it. An OpenSCENARIO trigger's
/// triggering entity ("Ego's speed > 20 m/s" in a story whose actor is another car); it does not
/// depend on the ego, so a WorldStory and the scenario machine may hold it.
class EntityCondition : public Condition {
public:
    /// Throws std::invalid_argument for an empty id or a null operand.
    EntityCondition(std::string vehicleId, ConditionPtr operand);

    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    traffic::SnapshotColumns columns() const override { return {}; }
    bool pure() const override { return operand_->pure(); }
    bool timeOnly() const override { return true; }
    void forEachChild(const std::function<void(Condition&)>& visit) const override { visit(*operand_); }
    std::string describe() const override;
    void check(CheckContext& ctx) const override;

    const std::string& vehicleId() const { return vehicleId_; }
    const ConditionPtr& operand() const { return operand_; }

private:
    std::string vehicleId_;
    ConditionPtr operand_;
};

}  // namespace sbsim::storyboard
