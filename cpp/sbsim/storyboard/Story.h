#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/Effect.h"
#include "sbsim/storyboard/StoryCounters.h"
#include "sbsim/storyboard/WorldEffect.h"

namespace sbsim::storyboard {

/// A condition tree and the effects applied to each vehicle while the tree holds for it (a
/// WorldStory: to the network while it holds).
class SBSIM_API Story {
public:
    /// Throws std::invalid_argument for a null condition or effect.
    Story(ConditionPtr condition, std::vector<EffectPtr> effects, std::optional<std::string> name = std::nullopt,
          std::optional<std::uint64_t> maxActivations = std::nullopt);
    virtual ~Story() = default;  // a WorldStory is one

    Condition& condition() const { return *condition_; }
    const ConditionPtr& conditionPtr() const { return condition_; }
    const std::vector<EffectPtr>& effects() const { return effects_; }
    /// The given name, or "story<N>" with N the registration index once registered.
    const std::string& name() const { return name_; }
    bool hasExplicitName() const { return explicitName_; }
    /// How often the story may activate per vehicle (then never again for it); none: unlimited.
    std::optional<std::uint64_t> maxActivations() const { return maxActivations_; }
    /// Whether the story acts on the network (a WorldStory) rather than on each vehicle.
    virtual bool isWorldStory() const { return false; }
    /// The effects on the network a WorldStory applies; none for a story on vehicles.
    virtual const std::vector<WorldEffectPtr>& worldEffects() const;

    /// What the story did so far in the run (the board counts).
    const StoryCounters& counters() const { return counters_; }
    StoryCounters& counters() { return counters_; }
    /// Names an unnamed story (the board: "story<N>"); a name the script gave stays.
    void setDefaultName(std::string name);

private:
    ConditionPtr condition_;
    std::vector<EffectPtr> effects_;
    std::string name_;
    bool explicitName_ = false;
    std::optional<std::uint64_t> maxActivations_;
    StoryCounters counters_;
};

using StoryPtr = std::shared_ptr<Story>;

}  // namespace sbsim::storyboard
