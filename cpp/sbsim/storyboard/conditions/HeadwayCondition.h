#pragma once

#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// Yields {leader} if the time gap to the vehicle ahead on the ego's route is below `seconds`:
/// gap (bumper to bumper) / ego speed, the leader searched by SUMO within max(100 m, speed ×
/// seconds × 2). A standing ego (speed < 0.1 m/s) has no headway: false. The leader is asked of
/// SUMO (EvaluationContext::queries) for each vehicle that reaches this condition, so put cheap
/// conditions before it in an All; for the same reason it runs on the board's own thread.
class HeadwayCondition : public Condition {
public:
    static constexpr double minLookAhead = 100;   ///< m
    static constexpr double standingSpeed = 0.1;  ///< m/s

    /// Throws std::invalid_argument for seconds <= 0 or not finite.
    explicit HeadwayCondition(double seconds);
    traffic::SnapshotColumns columns() const override { return {traffic::SnapshotColumns::Speed}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    std::string describe() const override;
    double seconds() const { return seconds_; }

private:
    double seconds_;
};

}  // namespace sbsim::storyboard
