#pragma once

#include <string>
#include <vector>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/SnapshotStamp.h"

namespace sbsim::storyboard {

/// True if the ego has stood (speed < 0.1 m/s) at every step for at least `duration` (its first
/// standing step counts as 0 s). Unlike HoldCondition it follows every vehicle at every step, in
/// prepare(), whether or not the condition is reached for it, so test() only reads and the
/// condition is pure; a vehicle missing from a snapshot starts again.
class StandstillCondition : public Condition {
public:
    static constexpr double standingSpeed = 0.1;  ///< m/s

    /// Throws std::invalid_argument for a negative duration.
    explicit StandstillCondition(kernel::SimTime duration);

    traffic::SnapshotColumns columns() const override { return {traffic::SnapshotColumns::Speed}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void prepare(const EvaluationContext& ctx) override;
    bool pure() const override { return true; }
    std::size_t heldVehicles() const override { return ids_.size(); }

    std::string describe() const override;
    kernel::SimTime duration() const { return duration_; }

private:
    kernel::SimTime duration_;
    SnapshotStamp stamp_;
    // The last prepared step's vehicles (ascending ids) and since when each stands (max: moving).
    std::vector<std::string> ids_;
    std::vector<kernel::SimTime> since_;
    std::vector<std::string> idScratch_;
    std::vector<kernel::SimTime> sinceScratch_;
};

}  // namespace sbsim::storyboard
