#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/WorldEffect.h"

namespace sbsim::storyboard {

/// A story about the network rather than its vehicles: its condition looks at time only and is
/// evaluated once per step, and while it holds its world effects act on the network (applied in
/// order on activation, removed in reverse order when it turns false). The board counts one
/// "vehicle" while it is active, so activations and active seconds read as for other stories.
class SBSIM_API WorldStory : public Story {
public:
    /// Throws std::invalid_argument for a null condition or effect, or a condition tree that does not
    /// look at time only (Condition::timeOnly), naming the first node that looks at more.
    WorldStory(ConditionPtr condition, std::vector<WorldEffectPtr> effects,
               std::optional<std::string> name = std::nullopt);

    bool isWorldStory() const override { return true; }
    const std::vector<WorldEffectPtr>& worldEffects() const override { return worldEffects_; }

private:
    std::vector<WorldEffectPtr> worldEffects_;
};

}  // namespace sbsim::storyboard
