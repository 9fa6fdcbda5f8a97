#include "sbsim/storyboard/SignalSpec.h"

#include <fmt/format.h>

#include <stdexcept>

namespace sbsim::storyboard {

void checkSignalSpec(std::string_view what, const std::string& tls, const std::string& state,
                     const std::vector<int>& links) {
    if (tls.empty()) throw std::invalid_argument(fmt::format("{} needs a traffic light id", what));
    if (state.empty()) throw std::invalid_argument(fmt::format("{} needs a state, one letter per signal", what));
    if (const auto bad = state.find_first_not_of(kSignalLetters); bad != std::string::npos) {
        throw std::invalid_argument(
            fmt::format("{} state '{}': '{}' is not a signal letter ({})", what, state, state[bad], kSignalLetters));
    }
    if (!links.empty() && state.size() != 1) {
        throw std::invalid_argument(
            fmt::format("{} state '{}' for links: one letter, which each link shows", what, state));
    }
    for (const int link : links) {
        if (link < 0) throw std::invalid_argument(fmt::format("{}: link {} < 0", what, link));
    }
}

}  // namespace sbsim::storyboard
