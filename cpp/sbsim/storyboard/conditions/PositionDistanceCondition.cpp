#include "sbsim/storyboard/conditions/PositionDistanceCondition.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "sbsim/storyboard/geometry/VehicleFootprint.h"

namespace sbsim::storyboard {

PositionDistanceCondition::PositionDistanceCondition(Eigen::Vector2d point, double value, ComparisonRule rule,
                                                     geometry::DistanceKind kind, bool freespace)
    : point_(point), value_(value), rule_(rule), kind_(kind), freespace_(freespace) {
    if (!point.allFinite()) throw std::invalid_argument("PositionDistanceCondition: the point must be finite");
    if (!std::isfinite(value) || value < 0) {
        throw std::invalid_argument(
            fmt::format("PositionDistanceCondition: the distance must be finite and >= 0, not {:g}", value));
    }
}

double PositionDistanceCondition::distance(const traffic::VehicleSnapshot& snapshot, VehicleIndex ego) const {
    const geometry::Footprint e = geometry::footprintOf(snapshot, ego);
    return geometry::distanceBetween(e, geometry::Footprint(point_, e.heading(), 0, 0), kind_, freespace_);
}

ConditionResult PositionDistanceCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    return compare(rule_, distance(ctx.snapshot(), ego), value_, kEqualTolerance);
}

std::string PositionDistanceCondition::describe() const {
    return fmt::format("PositionDistanceCondition(({:g}, {:g}), {} {}, {} {:g} m)", point_.x(), point_.y(),
                       geometry::distanceKindName(kind_), freespace_ ? "freespace" : "from the centre", ruleName(rule_),
                       value_);
}

}  // namespace sbsim::storyboard
