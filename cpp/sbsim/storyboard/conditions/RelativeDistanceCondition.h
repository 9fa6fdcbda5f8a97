#pragma once

#include <optional>
#include <string>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/ComparisonRule.h"
#include "sbsim/storyboard/conditions/SnapshotStamp.h"
#include "sbsim/storyboard/geometry/Distance.h"

namespace sbsim::storyboard {

/// OpenSCENARIO's RelativeDistanceCondition: the distance from the ego to vehicle `vehicle`,
/// compared by `rule` with `value` m; yields {vehicle} when true; false while that vehicle does
/// not run, and for that vehicle itself. Measured in the ego's frame (its heading):
/// longitudinal along it, lateral across it, cartesian straight; between the vehicles' centres
/// (reference points), or with `freespace` between their outlines (0 where they overlap), from
/// the snapshot's positions, headings, lengths and widths. equalTo holds within 0.01 m.
class RelativeDistanceCondition : public Condition {
public:
    using Kind = geometry::DistanceKind;
    static constexpr double kEqualTolerance = 0.01;  ///< m

    /// Throws std::invalid_argument for an empty id or a negative or non-finite value.
    RelativeDistanceCondition(std::string vehicle, double value, ComparisonRule rule, Kind kind, bool freespace);

    traffic::SnapshotColumns columns() const override {
        return {traffic::SnapshotColumns::Position, traffic::SnapshotColumns::Angle, traffic::SnapshotColumns::Size};
    }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void prepare(const EvaluationContext& ctx) override;
    bool pure() const override { return true; }
    std::string describe() const override;

    /// The distance (m) this condition measures from vehicle `ego` to vehicle `target` of `snapshot`.
    double distance(const traffic::VehicleSnapshot& snapshot, VehicleIndex ego, VehicleIndex target) const;

    const std::string& vehicle() const { return vehicle_; }
    double value() const { return value_; }
    ComparisonRule rule() const { return rule_; }
    Kind kind() const { return kind_; }
    bool freespace() const { return freespace_; }
    static std::string_view kindName(Kind kind);
    static std::optional<Kind> kindNamed(std::string_view name);

private:
    std::string vehicle_;
    double value_;
    ComparisonRule rule_;
    Kind kind_;
    bool freespace_;
    SnapshotStamp stamp_;
    std::optional<VehicleIndex> target_;
};

}  // namespace sbsim::storyboard
