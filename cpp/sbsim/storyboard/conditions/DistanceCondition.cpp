#include "sbsim/storyboard/conditions/DistanceCondition.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace sbsim::storyboard {

namespace {
double checkedDistance(double d) {
    if (!std::isfinite(d) || d < 0)
        throw std::invalid_argument("DistanceCondition: distance must be finite and >= 0, not " + std::to_string(d));
    return d;
}
}  // namespace

DistanceCondition::DistanceCondition(Eigen::Vector2d point, double distance)
    : point_(point), distance_(checkedDistance(distance)), distanceSquared_(distance * distance) {
    if (!point.allFinite()) throw std::invalid_argument("DistanceCondition: the point must be finite");
}

DistanceCondition::DistanceCondition(std::string vehicle, double distance)
    : vehicle_(std::move(vehicle)), distance_(checkedDistance(distance)), distanceSquared_(distance * distance) {
    if (vehicle_->empty()) throw std::invalid_argument("DistanceCondition: the target vehicle id is empty");
}

void DistanceCondition::prepare(const EvaluationContext& ctx) {
    if (!vehicle_) return;
    stamp_ = SnapshotStamp::of(ctx.snapshot());
    target_ = ctx.snapshot().indexOf(*vehicle_);
}

std::optional<VehicleIndex> DistanceCondition::targetIndex(const traffic::VehicleSnapshot& snapshot) const {
    if (stamp_ == SnapshotStamp::of(snapshot)) return target_;
    return snapshot.indexOf(*vehicle_);  // not prepared for this step
}

ConditionResult DistanceCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const auto& positions = ctx.snapshot().positions();
    if (point_) return (positions.col(ego) - *point_).squaredNorm() <= distanceSquared_;
    const std::optional<VehicleIndex> target = targetIndex(ctx.snapshot());
    if (!target || *target == ego) return ConditionResult::ofOthers({});
    if ((positions.col(ego) - positions.col(*target)).squaredNorm() > distanceSquared_)
        return ConditionResult::ofOthers({});
    return ConditionResult::ofOthers({*target});
}

std::string DistanceCondition::describe() const {
    const std::string target =
        vehicle_ ? fmt::format("vehicle {}", *vehicle_) : fmt::format("({:g}, {:g})", point_->x(), point_->y());
    return fmt::format("DistanceCondition({}, {:g} m)", target, distance_);
}

std::optional<ConditionArea> DistanceCondition::area() const {
    if (!point_) return std::nullopt;
    return ConditionArea{{*point_}, distance_};
}

}  // namespace sbsim::storyboard
