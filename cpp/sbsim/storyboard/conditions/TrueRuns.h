#pragma once

#include <optional>
#include <string_view>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/conditions/VehicleIdMap.h"

namespace sbsim::storyboard {

/// Per vehicle, when the current run of consecutive steps on which a condition was true began
/// (Hold and Rising). A step on which the condition was false, or was not evaluated for the
/// vehicle at all (an And stopped before it), ends the run. Only vehicles in a run are kept.
class TrueRuns {
public:
    /// Called with every step's time (from prepare() and test(); repeats are ignored), so a step
    /// that skipped the vehicle is noticed.
    void step(kernel::SimTime now) {
        if (current_ != now) {
            previous_ = current_;
            current_ = now;
        }
    }
    /// Records the condition's value for `id` at the current step and returns when its run began
    /// (the current step if it just began), or nothing if it is false. Calling it again in the
    /// same step (a condition shared by two stories) gives the same answer.
    std::optional<kernel::SimTime> record(std::string_view id, bool value);
    void forget(std::string_view id);
    std::size_t size() const { return runs_.size(); }

private:
    struct Run {
        kernel::SimTime since;
        kernel::SimTime last;
    };
    std::optional<kernel::SimTime> current_;
    std::optional<kernel::SimTime> previous_;
    VehicleIdMap<Run> runs_;
};

}  // namespace sbsim::storyboard
