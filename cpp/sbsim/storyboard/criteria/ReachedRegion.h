#pragma once

#include <optional>
#include <string>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Criterion.h"
#include "sbsim/storyboard/geometry/Polygon.h"

namespace sbsim::storyboard {

/// Passes when `vehicle`'s front bumper was inside `area` (SUMO coordinates) at some step no later
/// than `by`.
class ReachedRegion : public Criterion {
public:
    ReachedRegion(std::string vehicle, geometry::Polygon area, kernel::SimTime by);
    std::string describe() const override;
    traffic::SnapshotColumns columns() const override { return traffic::SnapshotColumns::Position; }
    void observe(const EvaluationContext& ctx) override;
    CriterionVerdict verdict(const CriterionRun& run) const override;

private:
    std::string vehicle_;
    geometry::Polygon area_;
    kernel::SimTime by_;
    std::optional<kernel::SimTime> reached_;  // first step inside
    bool seen_ = false;
};

}  // namespace sbsim::storyboard
