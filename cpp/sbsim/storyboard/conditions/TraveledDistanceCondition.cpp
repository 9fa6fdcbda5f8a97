#include "sbsim/storyboard/conditions/TraveledDistanceCondition.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace sbsim::storyboard {

TraveledDistanceCondition::TraveledDistanceCondition(double distance) : distance_(distance) {
    if (!std::isfinite(distance) || distance < 0) {
        throw std::invalid_argument(
            fmt::format("TraveledDistanceCondition: distance must be finite and >= 0, not {:g}", distance));
    }
}

ConditionResult TraveledDistanceCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    return ctx.queries().odometer(ctx.snapshot().ids()[ego]) >= distance_;
}

std::string TraveledDistanceCondition::describe() const {
    return fmt::format("TraveledDistanceCondition({:g} m)", distance_);
}

}  // namespace sbsim::storyboard
