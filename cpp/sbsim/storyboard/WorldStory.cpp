#include "sbsim/storyboard/WorldStory.h"

#include <stdexcept>

namespace sbsim::storyboard {

namespace {

/// The world has no ego to look at: every node must depend on time alone. Names the first leaf
/// (depth first) that does not, since a logic node is time-only exactly when its children are.
void requireTimeOnly(const Condition& c) {
    if (c.timeOnly()) return;
    const Condition* culprit = nullptr;
    c.forEachChild([&](const Condition& child) {
        if (culprit == nullptr && !child.timeOnly()) culprit = &child;
    });
    if (culprit != nullptr) return requireTimeOnly(*culprit);
    throw std::invalid_argument(
        "WorldStory conditions look at time only (TimeCondition, and Not/All/Any/Hold/Latch/"
        "Rising/And/Or over it), got " +
        c.typeName());
}

}  // namespace

WorldStory::WorldStory(ConditionPtr condition, std::vector<WorldEffectPtr> effects, std::optional<std::string> name)
    : Story(std::move(condition), {}, std::move(name)), worldEffects_(std::move(effects)) {
    for (const WorldEffectPtr& e : worldEffects_) {
        if (!e) throw std::invalid_argument("WorldStory effects must not contain None");
    }
    requireTimeOnly(this->condition());
}

}  // namespace sbsim::storyboard
