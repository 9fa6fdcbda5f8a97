#pragma once

#include <cstdint>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::storyboard {

/// What one story did in a run (the summary's figures): how often it activated, on how many
/// vehicles it is active now, and the time vehicles spent under it.
class SBSIM_API StoryCounters {
public:
    void activated() {
        ++activations_;
        ++activeVehicles_;
    }
    void deactivated() { --activeVehicles_; }
    /// `elapsed` passed with activeVehicles() vehicles under the story.
    void elapse(kernel::SimTime elapsed) {
        activeTime_ += elapsed * static_cast<kernel::SimTime::rep>(activeVehicles_);
    }

    std::uint64_t activations() const { return activations_; }
    /// Vehicles the story is active on now.
    std::uint64_t activeVehicles() const { return activeVehicles_; }
    /// The time vehicles spent under the story, summed over vehicles (a vehicle active from its
    /// activation step to its deactivation step counts that difference): a measure of how much a
    /// story did that, unlike activations, does not depend on how often it flickers.
    double activeVehicleSeconds() const { return activeTime_.seconds(); }

private:
    std::uint64_t activations_ = 0;
    std::uint64_t activeVehicles_ = 0;
    kernel::SimTime activeTime_;
};

}  // namespace sbsim::storyboard
