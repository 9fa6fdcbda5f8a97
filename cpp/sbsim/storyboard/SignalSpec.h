#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace sbsim::storyboard {

/// SUMO's signal letters (a traffic light's state is one per link).
inline constexpr std::string_view kSignalLetters = "GgrsuyYoO";

/// What a traffic-light condition or effect is given: the light `tls`, a `state` in SUMO's letters
/// (one letter when `links` names some of its links, each >= 0). Throws std::invalid_argument
/// starting with `what` (the condition's or effect's name) when it is not that.
void checkSignalSpec(std::string_view what, const std::string& tls, const std::string& state,
                     const std::vector<int>& links);

}  // namespace sbsim::storyboard
