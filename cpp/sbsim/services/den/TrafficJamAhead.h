#pragma once

#include <optional>

#include "sbsim/services/den/SampleBuffer.h"
#include "sbsim/services/den/UseCase.h"

namespace sbsim::services {

/// Artery's TrafficJamAhead: speed sampled every 1 s for 120 s. It sends (cause 1 traffic
/// condition; relevance < 1,000 m upstream; validity 60 s; a 1,000 m circle; repeated every 1 s
/// for 60 s; traffic class 1; then blocked 60 s) when the average speed over the last 120 s
/// (at least 10 s of samples) is above 0 and at most 30 km/h, or when the vehicle stood (average
/// 0 over the last 30 s, at least 10 s of samples) and it heard of a jam (a cause-1 DENM) or
/// knows from CAMs at least five slow vehicles (≤ 30 km/h, heading within 10°, within 100 m).
class TrafficJamAhead : public UseCase {
public:
    static constexpr int kCause = 1;

    void initialize() override;
    void check() override;

private:
    std::optional<SampleBuffer> speeds_;
    bool nonUrban_ = true;
};

}  // namespace sbsim::services
