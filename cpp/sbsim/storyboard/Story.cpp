#include "sbsim/storyboard/Story.h"

#include <stdexcept>

namespace sbsim::storyboard {

Story::Story(ConditionPtr condition, std::vector<EffectPtr> effects, std::optional<std::string> name,
             std::optional<std::uint64_t> maxActivations)
    : condition_(std::move(condition)), effects_(std::move(effects)), maxActivations_(maxActivations) {
    if (!condition_) throw std::invalid_argument("Story needs a condition, got None");
    for (const EffectPtr& e : effects_) {
        if (!e) throw std::invalid_argument("Story effects must not contain None");
    }
    if (name) {
        name_ = *name;
        explicitName_ = true;
    }
}

const std::vector<WorldEffectPtr>& Story::worldEffects() const {
    static const std::vector<WorldEffectPtr> none;
    return none;
}

}  // namespace sbsim::storyboard
