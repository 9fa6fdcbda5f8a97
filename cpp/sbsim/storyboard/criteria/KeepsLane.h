#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "sbsim/storyboard/Criterion.h"
#include "sbsim/storyboard/criteria/VehicleSet.h"

namespace sbsim::storyboard {

/// Passes when no vehicle of the set (all by default) changed lanes: between two steps, on the
/// same road, in another lane. Moving on to the next road (or through a junction) is no change.
class KeepsLane : public Criterion {
public:
    explicit KeepsLane(VehicleSet vehicles) : vehicles_(std::move(vehicles)) {}
    std::string describe() const override { return "KeepsLane(" + vehicles_.argument() + ")"; }
    traffic::SnapshotColumns columns() const override { return traffic::SnapshotColumns::Lane; }
    void observe(const EvaluationContext& ctx) override;
    CriterionVerdict verdict(const CriterionRun& run) const override;

private:
    struct Where {
        std::string road, lane;
    };
    VehicleSet vehicles_;
    std::unordered_map<std::string, Where> last_;  // per vehicle seen in the last step
    std::size_t changes_ = 0;
    std::string first_;
};

}  // namespace sbsim::storyboard
