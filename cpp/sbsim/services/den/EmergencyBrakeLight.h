#pragma once

#include <optional>

#include "sbsim/services/den/SampleBuffer.h"
#include "sbsim/services/den/UseCase.h"

namespace sbsim::services {

/// Artery's EmergencyBrakeLight: when the vehicle drives faster than 20 km/h and every
/// acceleration sample of the last 500 ms (sampled every 100 ms, the buffer full) is below
/// −7 m/s², it sends one DENM (cause 99 dangerous situation, sub-cause 1 emergency electronic
/// brake engaged; relevance < 500 m, all directions; validity 2 s; a 500 m circle; traffic class
/// 0); detection is then blocked for 100 ms. Attributes: speedThreshold (m/s),
/// decelerationThreshold (m/s²), sampleDuration, sampleInterval, detectionBlockingInterval (s).
class EmergencyBrakeLight : public UseCase {
public:
    static constexpr int kCause = 99;
    static constexpr int kSubcause = 1;

    void initialize() override;
    void check() override;

private:
    std::optional<SampleBuffer> samples_;
    double speedThreshold_ = 20 / 3.6;
    double decelerationThreshold_ = -7;
};

}  // namespace sbsim::services
