#pragma once

#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Object.h"
#include "sbsim/kernel/Signal.h"

namespace sbsim::traffic {

/// The contract between the storyboard and the services, kept below both: a story's SignalEffect
/// emits one (as the kernel signal `StoryboardSignal::id`) once, when its story activates for a
/// vehicle (and with an exit cause again when the story deactivates for it); the ego vehicle's
/// services receive it.
struct SBSIM_API StoryboardSignal : kernel::Object {
    /// The kernel signal a StoryboardSignal is emitted as.
    static const kernel::SignalId id;

    std::string cause;
    std::string story;
    std::string ego;
    std::vector<std::string> others;  ///< the condition's other vehicles, ascending (none on exit)
    bool onExit = false;              ///< sent as the story deactivated
};

}  // namespace sbsim::traffic
