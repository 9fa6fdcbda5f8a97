#include "sbsim/services/den/EmergencyBrakeLight.h"

#include <algorithm>

#include "sbsim/services/den/DenService.h"

namespace sbsim::services {

void EmergencyBrakeLight::initialize() {
    samples_.emplace(duration("sampleDuration", 0.5), duration("sampleInterval", 0.1));
    speedThreshold_ = number("speedThreshold", speedThreshold_);
    decelerationThreshold_ = number("decelerationThreshold", decelerationThreshold_);
    setDetectionBlockingInterval(duration("detectionBlockingInterval", 0.1));
}

void EmergencyBrakeLight::check() {
    samples_->feed(service().stationAcceleration(), service().now());
    if (isDetectionBlocked()) return;
    if (!(service().stationSpeed() > speedThreshold_)) return;
    const auto& s = samples_->samples();
    if (!samples_->full() || !std::all_of(s.begin(), s.end(), [&](const SampleBuffer::Sample& x) {
            return x.value < decelerationThreshold_;
        }))
        return;
    blockDetection();
    facilities::DenmContent denm = skeleton(500);
    denm.cause = kCause;
    denm.subcause = kSubcause;
    denm.relevanceDistance = 500;
    denm.validity = kernel::SimTime::fromSeconds(2);
    denm.trafficClass = 0;
    service().sendDenm(denm);
}

}  // namespace sbsim::services
