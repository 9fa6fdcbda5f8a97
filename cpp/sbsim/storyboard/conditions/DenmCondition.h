#pragma once

#include <memory>
#include <optional>
#include <string>

#include "sbsim/facilities/StationRegistry.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// Which of a station's DENM events count for a story beyond cause and age: the relevance a paper
/// asks of a warning ("warned of an event ahead within 500 m").
struct DenmRelevance {
    /// The event position at most this far (m, straight line) from the receiving vehicle.
    std::optional<double> within;
    /// The event lies in the receiver's driving direction (less than 90° off its heading).
    bool ahead = false;
    /// The receiver inside the event's relevance area: within its relevance distance of the event
    /// position when the DENM gives one, else inside its destination area.
    bool inRelevanceArea = false;

    bool any() const { return within || ahead || inRelevanceArea; }
};

/// True for a vehicle whose DENM memory holds an event (not expired, not terminated) with cause
/// code `cause` (any if none) that it heard — first or as a repetition — at most `maxAge` ago (any
/// time if none), and that passes `relevance` (the vehicle's position and heading against the
/// event's). Yields the set of the events' originating vehicles that are running; when none of
/// them is (an RSU, a vehicle gone), plainly true. Reads only the stations ctx.stations() has and,
/// with relevance filters, the snapshot's positions and angles: no state, so it runs on the pool.
class DenmCondition : public Condition {
public:
    DenmCondition(std::optional<int> cause, std::optional<kernel::SimTime> maxAge, DenmRelevance relevance = {});

    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    traffic::SnapshotColumns columns() const override;
    bool pure() const override { return true; }
    /// "DenmCondition(cause 6, max age 10 s, within 500 m, ahead)".
    std::string describe() const override;

    std::optional<int> cause() const { return cause_; }
    std::optional<kernel::SimTime> maxAge() const { return maxAge_; }
    const DenmRelevance& relevance() const { return relevance_; }

private:
    bool relevant(const facilities::DenmContent& denm, const Eigen::Vector2d& position, double angle) const;

    std::optional<int> cause_;
    std::optional<kernel::SimTime> maxAge_;
    DenmRelevance relevance_;
};

}  // namespace sbsim::storyboard
