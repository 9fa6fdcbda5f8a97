#include "sbsim/services/den/TractionLoss.h"

#include "sbsim/services/den/DenService.h"

namespace sbsim::services {

void TractionLoss::initialize() { setDetectionBlockingInterval(duration("detectionBlockingInterval", 20)); }

void TractionLoss::handleSignal(const traffic::StoryboardSignal& signal) {
    if (signal.cause == "traction loss") pending_ = true;
}

void TractionLoss::check() {
    if (!pending_ || isDetectionBlocked()) return;
    blockDetection();
    pending_ = false;
    facilities::DenmContent denm = skeleton(1000);
    denm.cause = kCause;
    denm.subcause = 0;
    denm.relevanceDistance = 100;
    denm.trafficDirection = facilities::TrafficDirection::All;
    denm.validity = kernel::SimTime::fromSeconds(600);
    denm.trafficClass = 1;
    service().sendDenm(denm, Repetition{kernel::SimTime::fromSeconds(1), kernel::SimTime::fromSeconds(300)});
}

}  // namespace sbsim::services
