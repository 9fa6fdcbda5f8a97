#pragma once

#include <memory>
#include <optional>
#include <string>

#include "sbsim/facilities/StationRegistry.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// True for a vehicle whose DENM memory holds an event (not expired, not terminated) with cause
/// code `cause` (any if none) that it heard — first or as a repetition — at most `maxAge` ago (any
/// time if none). Yields the set of the events' originating vehicles that are running; when none
/// of them is (an RSU, a vehicle gone), plainly true. Reads only the stations ctx.stations() has: no
/// snapshot column, no state, so it runs on the pool.
class DenmCondition : public Condition {
public:
    DenmCondition(std::optional<int> cause, std::optional<kernel::SimTime> maxAge);

    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    traffic::SnapshotColumns columns() const override { return {}; }
    bool pure() const override { return true; }
    /// "DenmCondition(cause 6, max age 10 s)".
    std::string describe() const override;

    std::optional<int> cause() const { return cause_; }
    std::optional<kernel::SimTime> maxAge() const { return maxAge_; }

private:
    std::optional<int> cause_;
    std::optional<kernel::SimTime> maxAge_;
};

}  // namespace sbsim::storyboard
