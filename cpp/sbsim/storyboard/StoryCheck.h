#pragma once

#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/storyboard/Criterion.h"
#include "sbsim/storyboard/Story.h"

namespace sbsim::storyboard {

/// One node of a story as `sbsim check` prints it: a condition or effect with its parameters.
struct SBSIM_API DescribedNode {
    int depth = 0;
    std::string text;
};

/// The story's condition tree (children indented one level) and then its effects (a world story's
/// world effects, after a first line "world story: acts on the network"), each as it describes itself.
SBSIM_API std::vector<DescribedNode> describeStory(const Story& story);
/// The warnings `sbsim check` gives for a story set, in story order: what each node of each story
/// reports of itself (each shared node once per story), then effects of one domain that fight.
SBSIM_API std::vector<CheckWarning> checkStories(const std::vector<StoryPtr>& stories, const CheckScenario& scenario);
/// The warnings for the criteria, in their order; each warning's `story` is the criterion's name.
SBSIM_API std::vector<CheckWarning> checkCriteria(const std::vector<CriterionPtr>& criteria,
                                                  const CheckScenario& scenario);

}  // namespace sbsim::storyboard
