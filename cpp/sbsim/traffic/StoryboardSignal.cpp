#include "sbsim/traffic/StoryboardSignal.h"

namespace sbsim::traffic {

const kernel::SignalId StoryboardSignal::id = kernel::registerSignal("storyboardSignal");

}  // namespace sbsim::traffic
