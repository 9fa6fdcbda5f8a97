#include "sbsim/storyboard/conditions/LimitCondition.h"

#include <fmt/format.h>

#include <stdexcept>
#include <string>

#include "sbsim/storyboard/CheckContext.h"

namespace sbsim::storyboard {

LimitCondition::LimitCondition(std::int64_t limit) : limit_(static_cast<std::uint64_t>(limit)) {
    if (limit < 0) throw std::invalid_argument(fmt::format("LimitCondition: limit must be >= 0, not {}", limit));
}

ConditionResult LimitCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const std::string& id = ctx.snapshot().ids()[ego];
    if (admitted_.contains(id)) return true;
    if (admittedCount_ >= limit_) return false;
    admitted_.insert(id);
    ++admittedCount_;
    return true;
}

void LimitCondition::forget(std::string_view vehicleId) {
    if (const auto it = admitted_.find(vehicleId); it != admitted_.end()) admitted_.erase(it);
}

std::string LimitCondition::describe() const { return fmt::format("LimitCondition({})", limit_); }

void LimitCondition::check(CheckContext& ctx) const {
    if (limit_ == 0) ctx.warn("LimitCondition(0) admits no vehicle: the story never activates");
}

}  // namespace sbsim::storyboard
