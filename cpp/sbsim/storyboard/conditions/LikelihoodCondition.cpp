#include "sbsim/storyboard/conditions/LikelihoodCondition.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sbsim::storyboard {

LikelihoodCondition::LikelihoodCondition(std::shared_ptr<kernel::RandomStream> rng, double p)
    : rng_(std::move(rng)), p_(std::clamp(p, 0.0, 1.0)) {
    if (!rng_) throw std::invalid_argument("LikelihoodCondition: random stream is null");
    if (std::isnan(p)) throw std::invalid_argument("LikelihoodCondition: probability must not be NaN");
}

ConditionResult LikelihoodCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const std::string& id = ctx.snapshot().ids()[ego];
    if (const auto it = decisions_.find(id); it != decisions_.end()) return it->second;
    // Drawn even for p = 0 or 1, so changing p does not shift the draws of later vehicles.
    const bool decision = rng_->uniform01() < p_;
    decisions_.emplace(id, decision);
    return decision;
}

void LikelihoodCondition::forget(std::string_view vehicleId) {
    if (const auto it = decisions_.find(vehicleId); it != decisions_.end()) decisions_.erase(it);
}

std::string LikelihoodCondition::describe() const { return fmt::format("LikelihoodCondition({:g})", p_); }

}  // namespace sbsim::storyboard
