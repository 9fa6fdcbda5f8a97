#include "sbsim/storyboard/conditions/DeferringCondition.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "sbsim/storyboard/DescribeText.h"

namespace sbsim::storyboard {

DeferringCondition::DeferringCondition(std::shared_ptr<kernel::RandomStream> rng, kernel::SimTime min,
                                       kernel::SimTime max)
    : rng_(std::move(rng)), min_(min), max_(max) {
    if (!rng_) throw std::invalid_argument("DeferringCondition: random stream is null");
    if (min_ < kernel::SimTime::zero()) {
        throw std::invalid_argument("DeferringCondition: min deferral " + min_.str() + " s is negative");
    }
    if (max_ < min_) {
        throw std::invalid_argument("DeferringCondition: max deferral " + max_.str() + " s is below min " + min_.str() +
                                    " s");
    }
}

ConditionResult DeferringCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const kernel::SimTime now = ctx.now();
    const std::string& id = ctx.snapshot().ids()[ego];
    if (const auto it = due_.find(id); it != due_.end()) return it->second <= now;
    // Uniform in [min, max], rounded to whole nanoseconds; the comparison keeps the cast in range.
    const kernel::SimTime::rep range = (max_ - min_).raw();
    const double offset = std::round(static_cast<double>(range) * rng_->uniform01());
    const kernel::SimTime::rep ns =
        offset < static_cast<double>(range) ? static_cast<kernel::SimTime::rep>(offset) : range;
    const kernel::SimTime due = now + min_ + kernel::SimTime::fromRaw(ns);
    due_.emplace(id, due);
    return due <= now;
}

void DeferringCondition::forget(std::string_view vehicleId) {
    if (const auto it = due_.find(vehicleId); it != due_.end()) due_.erase(it);
}

std::string DeferringCondition::describe() const {
    return fmt::format("DeferringCondition({} to {})", describeTime(min_), describeTime(max_));
}

}  // namespace sbsim::storyboard
