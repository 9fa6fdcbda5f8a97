#pragma once

#include <cstdint>
#include <string>

#include "sbsim/storyboard/Criterion.h"

namespace sbsim::storyboard {

/// Passes when the story named activated at least `atLeast` times (all vehicles together; a
/// WorldStory's activations). A name no registered story has fails, saying so.
class StoryActivated : public Criterion {
public:
    /// Throws std::invalid_argument for at_least below 1.
    StoryActivated(std::string story, std::int64_t atLeast);
    std::string describe() const override;
    CriterionVerdict verdict(const CriterionRun& run) const override;

private:
    std::string story_;
    std::uint64_t atLeast_;
};

}  // namespace sbsim::storyboard
