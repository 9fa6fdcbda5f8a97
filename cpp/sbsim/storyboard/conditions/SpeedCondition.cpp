#include "sbsim/storyboard/conditions/SpeedCondition.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace sbsim::storyboard {

namespace {
double checkedThreshold(double mps, const char* what) {
    if (std::isnan(mps)) throw std::invalid_argument(std::string(what) + ": speed must not be NaN");
    return mps;
}
}  // namespace

SpeedConditionGreater::SpeedConditionGreater(double mps) : threshold_(checkedThreshold(mps, "SpeedConditionGreater")) {}

ConditionResult SpeedConditionGreater::test(const EvaluationContext& ctx, VehicleIndex ego) {
    return ctx.snapshot().speeds()[ego] > threshold_;
}

SpeedConditionLess::SpeedConditionLess(double mps) : threshold_(checkedThreshold(mps, "SpeedConditionLess")) {}

ConditionResult SpeedConditionLess::test(const EvaluationContext& ctx, VehicleIndex ego) {
    return ctx.snapshot().speeds()[ego] < threshold_;
}

std::string SpeedConditionGreater::describe() const {
    return fmt::format("SpeedConditionGreater({:g} m/s)", threshold_);
}

std::string SpeedConditionLess::describe() const { return fmt::format("SpeedConditionLess({:g} m/s)", threshold_); }

}  // namespace sbsim::storyboard
