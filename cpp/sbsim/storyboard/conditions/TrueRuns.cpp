#include "sbsim/storyboard/conditions/TrueRuns.h"

#include <cassert>

namespace sbsim::storyboard {

std::optional<kernel::SimTime> TrueRuns::record(std::string_view id, bool value) {
    assert(current_.has_value());
    const kernel::SimTime now = *current_;
    auto it = runs_.find(id);
    if (!value) {
        if (it != runs_.end()) runs_.erase(it);
        return std::nullopt;
    }
    if (it == runs_.end()) {
        it = runs_.emplace(std::string(id), Run{now, now}).first;
    } else if (it->second.last != now && it->second.last != previous_) {
        it->second = Run{now, now};  // a gap: the last true step was not the previous step
    } else {
        it->second.last = now;
    }
    return it->second.since;
}

void TrueRuns::forget(std::string_view id) {
    if (const auto it = runs_.find(id); it != runs_.end()) runs_.erase(it);
}

}  // namespace sbsim::storyboard
