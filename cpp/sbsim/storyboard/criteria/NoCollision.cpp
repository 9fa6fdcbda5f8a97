#include "sbsim/storyboard/criteria/NoCollision.h"

#include <fmt/format.h>

namespace sbsim::storyboard {

void NoCollision::observe(const EvaluationContext& ctx) {
    for (const auto& c : ctx.queries().collisions(ctx.now())) {
        if (collisions_++ == 0) first_ = fmt::format("{} with {} at t={} s", c.collider, c.victim, ctx.now().str());
    }
}

CriterionVerdict NoCollision::verdict(const CriterionRun& /*run*/) const {
    if (collisions_ == 0) return {true, "0 collisions", "0 collisions"};
    return {false, fmt::format("{} collision{}, first {}", collisions_, collisions_ == 1 ? "" : "s", first_),
            "0 collisions"};
}

}  // namespace sbsim::storyboard
