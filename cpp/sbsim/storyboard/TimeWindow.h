#pragma once

#include <algorithm>
#include <optional>

#include "sbsim/kernel/SimTime.h"

namespace sbsim::storyboard {

/// The times [begin, end] outside which a condition is false, whoever the ego.
struct TimeWindow {
    kernel::SimTime begin;
    kernel::SimTime end;

    /// Whether no time lies strictly inside it (`sbsim check`'s test for windows that never overlap).
    bool empty() const { return begin >= end; }
};

/// The window both bound a conjunction to: their intersection, or the one that is given.
inline std::optional<TimeWindow> intersect(const std::optional<TimeWindow>& a, const std::optional<TimeWindow>& b) {
    if (!a) return b;
    if (!b) return a;
    return TimeWindow{std::max(a->begin, b->begin), std::min(a->end, b->end)};
}

}  // namespace sbsim::storyboard
