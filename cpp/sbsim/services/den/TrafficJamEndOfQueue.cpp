#include "sbsim/services/den/TrafficJamEndOfQueue.h"

#include "sbsim/services/den/DenService.h"

namespace sbsim::services {

void TrafficJamEndOfQueue::initialize() {
    speeds_.emplace(duration("sampleDuration", 10), duration("sampleInterval", 0.1));
    nonUrban_ = number("nonUrbanEnvironment", 1) != 0;
    setDetectionBlockingInterval(duration("detectionBlockingInterval", 60));
}

bool TrafficJamEndOfQueue::egoDecelerated() const {
    const auto& s = speeds_->samples();
    if (s.empty() || s.front().value > 30 / 3.6) return false;
    for (std::size_t i = 1; i < s.size(); ++i) {
        if (s[i].value >= 80 / 3.6) {
            const double dt = (s.front().time - s[i].time).seconds();
            return dt > 0 && (s.front().value - s[i].value) / dt < -3.5;
        }
    }
    return false;
}

void TrafficJamEndOfQueue::check() {
    speeds_->feed(service().stationSpeed(), service().now());
    if (isDetectionBlocked() || !nonUrban_) return;
    const auto& memory = service().memory();
    const kernel::SimTime now = service().now();
    const bool heard = memory.count(kCause, now) >= 1 || memory.count(1, now) >= 5;
    if (!(egoDecelerated() && heard)) return;
    blockDetection();
    facilities::DenmContent denm = skeleton(1000);
    denm.cause = kCause;
    denm.relevanceDistance = 1000;
    denm.trafficDirection = facilities::TrafficDirection::Upstream;
    denm.validity = kernel::SimTime::fromSeconds(20);
    denm.trafficClass = 1;
    service().sendDenm(denm, Repetition{kernel::SimTime::fromMilliseconds(500), kernel::SimTime::fromSeconds(20)});
}

}  // namespace sbsim::services
