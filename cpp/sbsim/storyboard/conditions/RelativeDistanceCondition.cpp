#include "sbsim/storyboard/conditions/RelativeDistanceCondition.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "sbsim/storyboard/geometry/VehicleFootprint.h"

namespace sbsim::storyboard {

RelativeDistanceCondition::RelativeDistanceCondition(std::string vehicle, double value, ComparisonRule rule, Kind kind,
                                                     bool freespace)
    : vehicle_(std::move(vehicle)), value_(value), rule_(rule), kind_(kind), freespace_(freespace) {
    if (vehicle_.empty()) throw std::invalid_argument("RelativeDistanceCondition: the vehicle id is empty");
    if (!std::isfinite(value) || value < 0) {
        throw std::invalid_argument(
            fmt::format("RelativeDistanceCondition: the distance must be finite and >= 0, not {:g}", value));
    }
}

void RelativeDistanceCondition::prepare(const EvaluationContext& ctx) {
    stamp_ = SnapshotStamp::of(ctx.snapshot());
    target_ = ctx.snapshot().indexOf(vehicle_);
}

double RelativeDistanceCondition::distance(const traffic::VehicleSnapshot& snapshot, VehicleIndex ego,
                                           VehicleIndex target) const {
    return geometry::distanceBetween(geometry::footprintOf(snapshot, ego), geometry::footprintOf(snapshot, target),
                                     kind_, freespace_);
}

ConditionResult RelativeDistanceCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const traffic::VehicleSnapshot& snapshot = ctx.snapshot();
    const std::optional<VehicleIndex> target =
        stamp_ == SnapshotStamp::of(snapshot) ? target_ : snapshot.indexOf(vehicle_);
    if (!target || *target == ego) return ConditionResult::ofOthers({});
    if (!compare(rule_, distance(snapshot, ego, *target), value_, kEqualTolerance))
        return ConditionResult::ofOthers({});
    return ConditionResult::ofOthers({*target});
}

std::string_view RelativeDistanceCondition::kindName(Kind kind) { return geometry::distanceKindName(kind); }

std::optional<RelativeDistanceCondition::Kind> RelativeDistanceCondition::kindNamed(std::string_view name) {
    for (const Kind k : {Kind::Longitudinal, Kind::Lateral, Kind::Cartesian}) {
        if (kindName(k) == name) return k;
    }
    return std::nullopt;
}

std::string RelativeDistanceCondition::describe() const {
    return fmt::format("RelativeDistanceCondition(vehicle {}, {} {}, {} {:g} m)", vehicle_, kindName(kind_),
                       freespace_ ? "freespace" : "reference points", ruleName(rule_), value_);
}

}  // namespace sbsim::storyboard
