#pragma once

#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Object.h"

namespace sbsim::storyboard {

/// Emitted by a SignalEffect once, when its story activates for a vehicle (and with an exit cause
/// again when the story deactivates for it): delivered to the ego vehicle's services (and to anyone
/// subscribed to Storyboard::signalEmitted).
struct SBSIM_API StoryboardSignal : kernel::Object {
    std::string cause;
    std::string story;
    std::string ego;
    std::vector<std::string> others;  ///< the condition's other vehicles, ascending (none on exit)
    bool onExit = false;              ///< sent as the story deactivated
};

}  // namespace sbsim::storyboard
