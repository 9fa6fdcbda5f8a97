#pragma once

#include <Eigen/Core>
#include <string>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/ComparisonRule.h"
#include "sbsim/storyboard/geometry/Distance.h"

namespace sbsim::storyboard {

/// OpenSCENARIO's DistanceCondition to a position: the distance from the ego to the point `point`
/// (SUMO coordinates), compared by `rule` with `value` m, measured as RelativeDistanceCondition
/// measures between vehicles: in the ego's frame (longitudinal along its heading, lateral across
/// it, cartesian straight), from the ego's centre, or with `freespace` from its outline.
/// equalTo holds within 0.01 m.
class PositionDistanceCondition : public Condition {
public:
    static constexpr double kEqualTolerance = 0.01;  ///< m

    /// Throws std::invalid_argument for a non-finite point or a negative or non-finite value.
    PositionDistanceCondition(Eigen::Vector2d point, double value, ComparisonRule rule, geometry::DistanceKind kind,
                              bool freespace);

    traffic::SnapshotColumns columns() const override {
        return {traffic::SnapshotColumns::Position, traffic::SnapshotColumns::Angle, traffic::SnapshotColumns::Size};
    }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    bool pure() const override { return true; }
    std::string describe() const override;

    /// The distance (m) this condition measures from vehicle `ego` of `snapshot` to its point.
    double distance(const traffic::VehicleSnapshot& snapshot, VehicleIndex ego) const;

    const Eigen::Vector2d& point() const { return point_; }
    double value() const { return value_; }
    ComparisonRule rule() const { return rule_; }
    geometry::DistanceKind kind() const { return kind_; }
    bool freespace() const { return freespace_; }

private:
    Eigen::Vector2d point_;
    double value_;
    ComparisonRule rule_;
    geometry::DistanceKind kind_;
    bool freespace_;
};

}  // namespace sbsim::storyboard
