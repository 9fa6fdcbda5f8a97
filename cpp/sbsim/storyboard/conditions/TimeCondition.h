#pragma once

#include <optional>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// True while begin <= now <= end (end: forever when not given).
class TimeCondition : public Condition {
public:
    /// Throws std::invalid_argument if end < begin.
    TimeCondition(kernel::SimTime begin, std::optional<kernel::SimTime> end = std::nullopt);

    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;

    std::string describe() const override;
    bool timeOnly() const override { return true; }
    std::optional<TimeWindow> timeWindow() const override { return TimeWindow{begin_, end_}; }
    /// Warns about a window outside the run.
    void check(CheckContext& ctx) const override;
    kernel::SimTime begin() const { return begin_; }
    kernel::SimTime end() const { return end_; }

    bool pure() const override { return true; }

private:
    kernel::SimTime begin_;
    kernel::SimTime end_;
};

}  // namespace sbsim::storyboard
