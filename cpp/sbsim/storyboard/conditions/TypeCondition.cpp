#include "sbsim/storyboard/conditions/TypeCondition.h"

#include <fmt/format.h>
#include <re2/re2.h>

#include <stdexcept>

namespace sbsim::storyboard {

TypeCondition::TypeCondition(const std::string& pattern)
    : pattern_(pattern), regex_(std::make_unique<re2::RE2>(pattern, re2::RE2::Quiet)) {
    if (!regex_->ok()) throw std::invalid_argument("TypeCondition: bad pattern '" + pattern + "': " + regex_->error());
}

TypeCondition::~TypeCondition() = default;

ConditionResult TypeCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const auto matches = [this](const std::string& type) { return re2::RE2::FullMatch(type, *regex_); };
    return verdicts_.passes(ctx.snapshot(), ctx.snapshot().typeKey(ego), matches);
}

void TypeCondition::prepare(const EvaluationContext& ctx) {
    verdicts_.update(ctx.snapshot(), [this](const std::string& type) { return re2::RE2::FullMatch(type, *regex_); });
}

std::string TypeCondition::describe() const { return fmt::format("TypeCondition('{}')", pattern_); }

}  // namespace sbsim::storyboard
