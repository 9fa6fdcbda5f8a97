#include "sbsim/storyboard/conditions/AccelerationCondition.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace sbsim::storyboard {

namespace {
double checkedThreshold(double a, const char* what) {
    if (std::isnan(a)) throw std::invalid_argument(std::string(what) + ": acceleration must not be NaN");
    return a;
}
}  // namespace

AccelerationConditionGreater::AccelerationConditionGreater(double threshold)
    : threshold_(checkedThreshold(threshold, "AccelerationConditionGreater")) {}

AccelerationConditionLess::AccelerationConditionLess(double threshold)
    : threshold_(checkedThreshold(threshold, "AccelerationConditionLess")) {}

std::string AccelerationConditionGreater::describe() const {
    return fmt::format("AccelerationConditionGreater({:g} m/s²)", threshold_);
}

std::string AccelerationConditionLess::describe() const {
    return fmt::format("AccelerationConditionLess({:g} m/s²)", threshold_);
}

}  // namespace sbsim::storyboard
