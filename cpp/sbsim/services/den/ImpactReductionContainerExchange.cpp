#include "sbsim/services/den/ImpactReductionContainerExchange.h"

#include "sbsim/services/den/DenService.h"

namespace sbsim::services {

void ImpactReductionContainerExchange::handleSignal(const traffic::StoryboardSignal& signal) {
    if (signal.cause == "irc") pendingRequest_ = true;
}

void ImpactReductionContainerExchange::check() {
    if (!pendingRequest_) return;
    pendingRequest_ = false;
    transmit(facilities::ImpactReduction::Request);
}

void ImpactReductionContainerExchange::indicate(const facilities::Denm& denm) {
    const auto& c = denm.content();
    if (c.cause == kCause && c.impactReduction == facilities::ImpactReduction::Request)
        transmit(facilities::ImpactReduction::Response);
}

void ImpactReductionContainerExchange::transmit(facilities::ImpactReduction indication) {
    facilities::DenmContent denm = skeleton(100);
    denm.cause = kCause;
    denm.relevanceDistance = 100;
    denm.validity = kernel::SimTime::fromSeconds(2);
    denm.trafficClass = 0;
    denm.impactReduction = indication;
    service().sendDenm(denm,
                       Repetition{kernel::SimTime::fromMilliseconds(100), kernel::SimTime::fromMilliseconds(300)});
}

}  // namespace sbsim::services
