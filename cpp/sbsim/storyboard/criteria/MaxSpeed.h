#pragma once

#include <string>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Criterion.h"
#include "sbsim/storyboard/criteria/VehicleSet.h"

namespace sbsim::storyboard {

/// Passes when no vehicle of the set (all by default) was ever faster than `mps` after a step.
class MaxSpeed : public Criterion {
public:
    /// Throws std::invalid_argument for a limit that is negative or not finite.
    MaxSpeed(double mps, VehicleSet vehicles);
    std::string describe() const override;
    traffic::SnapshotColumns columns() const override { return traffic::SnapshotColumns::Speed; }
    void observe(const EvaluationContext& ctx) override;
    CriterionVerdict verdict(const CriterionRun& run) const override;

private:
    double limit_;
    VehicleSet vehicles_;
    double fastest_ = -1;  // none seen yet
    std::string who_;
    kernel::SimTime when_;
};

}  // namespace sbsim::storyboard
