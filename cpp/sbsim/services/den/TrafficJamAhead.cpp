#include "sbsim/services/den/TrafficJamAhead.h"

#include "sbsim/services/ca/CamGenerationRules.h"
#include "sbsim/services/den/DenService.h"

namespace sbsim::services {

void TrafficJamAhead::initialize() {
    speeds_.emplace(duration("sampleDuration", 120), duration("sampleInterval", 1));
    nonUrban_ = number("nonUrbanEnvironment", 1) != 0;
    setDetectionBlockingInterval(duration("detectionBlockingInterval", 60));
}

void TrafficJamAhead::check() {
    const kernel::SimTime now = service().now();
    speeds_->feed(service().stationSpeed(), now);
    if (isDetectionBlocked() || !nonUrban_) return;
    const kernel::SimTime tenSeconds = kernel::SimTime::fromSeconds(10);

    const auto window = speeds_->notBefore(now - kernel::SimTime::fromSeconds(120));
    bool lowAverage = false;
    if (SampleBuffer::span(window) >= tenSeconds) {
        const double average = SampleBuffer::average(window);
        lowAverage = average > 0 && average <= 30 / 3.6;
    }
    bool stationary = false;
    const auto recent = speeds_->notBefore(now - kernel::SimTime::fromSeconds(30));
    if (SampleBuffer::span(recent) >= tenSeconds) stationary = SampleBuffer::average(recent) <= 0;

    bool trigger = lowAverage;
    if (!trigger && stationary) {
        const bool heard = service().memory().count(kCause, now) >= 1;
        const Eigen::Vector2d here = service().stationPosition();
        const double heading = service().stationHeading();
        const std::size_t slow = service().ldm().count(now, [&](const facilities::LocalDynamicMap::Entry& e) {
            return e.cam.speed <= 8.33 && CamGenerationRules::headingDifference(e.cam.heading, heading) <= 10 &&
                   (e.cam.position - here).norm() <= 100;
        });
        trigger = heard || slow >= 5;
    }
    if (!trigger) return;
    blockDetection();
    facilities::DenmContent denm = skeleton(1000);
    denm.cause = kCause;
    denm.relevanceDistance = 1000;
    denm.trafficDirection = facilities::TrafficDirection::Upstream;
    denm.validity = kernel::SimTime::fromSeconds(60);
    denm.trafficClass = 1;
    service().sendDenm(denm, Repetition{kernel::SimTime::fromSeconds(1), kernel::SimTime::fromSeconds(60)});
}

}  // namespace sbsim::services
