#pragma once

#include <optional>

#include "sbsim/services/den/SampleBuffer.h"
#include "sbsim/services/den/UseCase.h"

namespace sbsim::services {

/// Artery's TrafficJamEndOfQueue: speed sampled every 100 ms for 10 s. It sends (cause 27
/// dangerous end of queue; relevance < 1,000 m upstream; validity 20 s; a 1,000 m circle; repeated
/// every 0.5 s for 20 s; traffic class 1; then blocked 60 s) when the vehicle braked hard to a
/// queue — now at most 30 km/h, and from the newest earlier sample of at least 80 km/h it
/// decelerated by more than 3.5 m/s² on average — and it heard of a queue: an end-of-queue DENM
/// (cause 27) or at least five traffic-jam DENMs (cause 1) in its memory. Only outside towns
/// (nonUrbanEnvironment, default true).
class TrafficJamEndOfQueue : public UseCase {
public:
    static constexpr int kCause = 27;

    void initialize() override;
    void check() override;
    /// Artery's ego deceleration test on the speed samples.
    bool egoDecelerated() const;

private:
    std::optional<SampleBuffer> speeds_;
    bool nonUrban_ = true;
};

}  // namespace sbsim::services
