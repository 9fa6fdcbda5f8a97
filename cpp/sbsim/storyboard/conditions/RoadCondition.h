#pragma once

#include <set>
#include <string>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/InternedVerdicts.h"

namespace sbsim::storyboard {

/// True if the ego drives on one of the given roads (SUMO edge ids; the internal edges of
/// junctions, ":J3_0", are roads too).
class RoadCondition : public Condition {
public:
    explicit RoadCondition(std::set<std::string> ids) : ids_(std::move(ids)) {}
    traffic::SnapshotColumns columns() const override { return {traffic::SnapshotColumns::Lane}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void prepare(const EvaluationContext& ctx) override;
    bool pure() const override { return true; }
    std::string describe() const override;
    /// Warns about ids the network has no edge of.
    void check(CheckContext& ctx) const override;
    const std::set<std::string>& ids() const { return ids_; }

private:
    std::set<std::string> ids_;
    InternedVerdicts verdicts_;
};

}  // namespace sbsim::storyboard
