#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/SnapshotStamp.h"

namespace sbsim::storyboard {

/// True if the ego's position (front bumper centre) is within `distance` m (inclusive) of a fixed
/// point (SUMO network coordinates) or of another vehicle's position. A vehicle target yields the
/// set {target} when within; it is false while the target is not running, and for the target
/// itself (a set names other vehicles).
class DistanceCondition : public Condition {
public:
    /// Throws std::invalid_argument for a negative or non-finite distance or a non-finite point.
    DistanceCondition(Eigen::Vector2d point, double distance);
    /// Throws std::invalid_argument for a negative or non-finite distance or an empty id.
    DistanceCondition(std::string vehicle, double distance);

    traffic::SnapshotColumns columns() const override { return {traffic::SnapshotColumns::Position}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    /// Finds the target vehicle once per step.
    void prepare(const EvaluationContext& ctx) override;
    bool pure() const override { return true; }

    std::string describe() const override;
    /// A circle around a fixed point; none around a vehicle.
    std::optional<ConditionArea> area() const override;
    double distance() const { return distance_; }
    const std::optional<Eigen::Vector2d>& point() const { return point_; }
    const std::optional<std::string>& vehicle() const { return vehicle_; }

private:
    std::optional<VehicleIndex> targetIndex(const traffic::VehicleSnapshot& snapshot) const;

    std::optional<Eigen::Vector2d> point_;
    std::optional<std::string> vehicle_;
    double distance_;
    double distanceSquared_;
    SnapshotStamp stamp_;
    std::optional<VehicleIndex> target_;  // the target's index in the stamped snapshot
};

}  // namespace sbsim::storyboard
