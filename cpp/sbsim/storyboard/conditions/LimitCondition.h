#pragma once

#include <cstdint>
#include <string_view>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/VehicleIdMap.h"

namespace sbsim::storyboard {

/// True for the first `limit` distinct vehicles that reach (are tested by) this condition, and for
/// them only, for as long as they run. A vehicle that leaves does not free its slot.
class LimitCondition : public Condition {
public:
    /// Throws std::invalid_argument for a negative limit.
    explicit LimitCondition(std::int64_t limit);

    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void forget(std::string_view vehicleId) override;
    std::size_t heldVehicles() const override { return admitted_.size(); }

    std::string describe() const override;
    /// Warns about a limit of 0: the story never activates.
    void check(CheckContext& ctx) const override;
    std::uint64_t limit() const { return limit_; }
    /// How many vehicles were ever admitted (never decreases).
    std::uint64_t admittedCount() const { return admittedCount_; }

private:
    std::uint64_t limit_;
    std::uint64_t admittedCount_ = 0;
    VehicleIdSet admitted_;  // admitted and still running
};

}  // namespace sbsim::storyboard
