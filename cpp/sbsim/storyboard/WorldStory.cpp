#include "sbsim/storyboard/WorldStory.h"

#include <stdexcept>

#include "sbsim/storyboard/conditions/AllCondition.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/AnyCondition.h"
#include "sbsim/storyboard/conditions/HoldCondition.h"
#include "sbsim/storyboard/conditions/NotCondition.h"
#include "sbsim/storyboard/conditions/OrCondition.h"
#include "sbsim/storyboard/conditions/RisingCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"

namespace sbsim::storyboard {

namespace {

/// Only nodes whose value depends on time alone: the world has no ego to look at.
void requireTimeOnly(Condition& c) {
    const bool timeOnly = dynamic_cast<TimeCondition*>(&c) || dynamic_cast<NotCondition*>(&c) ||
                          dynamic_cast<AllCondition*>(&c) || dynamic_cast<AnyCondition*>(&c) ||
                          dynamic_cast<HoldCondition*>(&c) || dynamic_cast<RisingCondition*>(&c) ||
                          dynamic_cast<AndCondition*>(&c) || dynamic_cast<OrCondition*>(&c);
    if (!timeOnly) {
        throw std::invalid_argument(
            "WorldStory conditions look at time only (TimeCondition, and Not/All/Any/Hold/"
            "Rising/And/Or over it), got " +
            c.typeName());
    }
    c.forEachChild(requireTimeOnly);
}

}  // namespace

WorldStory::WorldStory(ConditionPtr condition, std::vector<WorldEffectPtr> effects, std::optional<std::string> name)
    : Story(std::move(condition), {}, std::move(name)), worldEffects_(std::move(effects)) {
    for (const WorldEffectPtr& e : worldEffects_) {
        if (!e) throw std::invalid_argument("WorldStory effects must not contain None");
    }
    requireTimeOnly(this->condition());
    markWorld();
}

}  // namespace sbsim::storyboard
