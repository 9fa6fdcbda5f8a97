#include "sbsim/services/den/StoryboardEvent.h"

#include "sbsim/services/ServicesConfig.h"
#include "sbsim/services/den/DenService.h"

namespace sbsim::services {

void StoryboardEvent::initialize() {
    const auto signal = text("signal");
    if (!signal || signal->empty()) {
        throw ServicesConfigError(service().spec().source + ":" + std::to_string(service().spec().line) +
                                  ": the StoryboardEvent use case needs a 'signal' attribute");
    }
    signal_ = *signal;
    endSignal_ = text("endSignal");
}

void StoryboardEvent::handleSignal(const traffic::StoryboardSignal& signal) {
    if (endSignal_ && signal.cause == *endSignal_) {
        // Ended at once (not at the next trigger), so no repetition goes out after the story ended.
        pending_ = false;
        if (event_) service().terminate(*event_);
        event_.reset();
    } else if (signal.cause == signal_ && !signal.onExit) {
        pending_ = true;
    }
}

void StoryboardEvent::check() {
    // The event starts at the trigger, as Artery's use cases do.
    if (!pending_) return;
    pending_ = false;
    if (event_ && service().repeating(*event_)) return;  // still going
    const kernel::SimTime validity = duration("validity", 600);
    facilities::DenmContent denm = skeleton(number("area", 1000));
    denm.cause = static_cast<int>(number("cause", 0));
    denm.subcause = static_cast<int>(number("subcause", 0));
    if (text("relevance")) denm.relevanceDistance = number("relevance", 0);
    denm.validity = validity;
    denm.trafficClass = static_cast<int>(number("trafficClass", 1));
    event_ = denm.action;
    service().sendDenm(denm, Repetition{duration("interval", 1), duration("duration", validity.seconds())});
}

}  // namespace sbsim::services
