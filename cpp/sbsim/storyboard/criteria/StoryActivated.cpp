#include "sbsim/storyboard/criteria/StoryActivated.h"

#include <fmt/format.h>

#include <stdexcept>

namespace sbsim::storyboard {

StoryActivated::StoryActivated(std::string story, std::int64_t atLeast) : story_(std::move(story)) {
    if (atLeast < 1) throw std::invalid_argument(fmt::format("StoryActivated: at_least must be >= 1, got {}", atLeast));
    atLeast_ = static_cast<std::uint64_t>(atLeast);
}

std::string StoryActivated::describe() const {
    return fmt::format("StoryActivated({}, at_least={})", story_, atLeast_);
}

CriterionVerdict StoryActivated::verdict(const CriterionRun& run) const {
    const std::string expected = fmt::format(">= {} activations", atLeast_);
    for (const StoryPtr& s : run.stories) {
        if (s->name() != story_) continue;
        const std::uint64_t n = s->counters().activations();
        return {n >= atLeast_, fmt::format("{} activations", n), expected};
    }
    return {false, fmt::format("no story named {}", story_), expected};
}

}  // namespace sbsim::storyboard
