#pragma once

#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// OpenSCENARIO's TraveledDistanceCondition: true once the ego has driven at least `distance` m
/// since it departed (SUMO's odometer; for a scenario's entities, which depart at its start, the
/// standard's "since the start"). The odometer is asked of SUMO (EvaluationContext::queries) for
/// each vehicle that reaches this condition, so put cheap conditions before it in an All; for the
/// same reason it runs on the board's own thread.
class TraveledDistanceCondition : public Condition {
public:
    /// Throws std::invalid_argument for a negative or non-finite distance.
    explicit TraveledDistanceCondition(double distance);
    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    std::string describe() const override;
    double distance() const { return distance_; }

private:
    double distance_;
};

}  // namespace sbsim::storyboard
