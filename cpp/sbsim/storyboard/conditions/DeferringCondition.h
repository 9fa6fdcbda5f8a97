#pragma once

#include <memory>
#include <string_view>

#include "sbsim/kernel/RandomStream.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/VehicleIdMap.h"

namespace sbsim::storyboard {

/// Becomes true for a vehicle a random time after its first evaluation, as Artery's
/// DeferringCondition: the first evaluation draws a deferral uniform in [min, max] and remembers
/// now + deferral; the condition is true once now >= that time (on the first evaluation only for
/// a zero deferral).
class DeferringCondition : public Condition {
public:
    /// Throws std::invalid_argument for a null stream, a negative min or max < min.
    DeferringCondition(std::shared_ptr<kernel::RandomStream> rng, kernel::SimTime min, kernel::SimTime max);

    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void forget(std::string_view vehicleId) override;
    std::size_t heldVehicles() const override { return due_.size(); }

    std::string describe() const override;
    kernel::SimTime minDeferral() const { return min_; }
    kernel::SimTime maxDeferral() const { return max_; }

private:
    std::shared_ptr<kernel::RandomStream> rng_;
    kernel::SimTime min_;
    kernel::SimTime max_;
    VehicleIdMap<kernel::SimTime> due_;
};

}  // namespace sbsim::storyboard
