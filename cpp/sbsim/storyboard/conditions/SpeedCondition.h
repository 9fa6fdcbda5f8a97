#pragma once

#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// True if the ego's speed is strictly above the threshold (m/s).
class SpeedConditionGreater : public Condition {
public:
    explicit SpeedConditionGreater(double mps);
    traffic::SnapshotColumns columns() const override { return {traffic::SnapshotColumns::Speed}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    std::string describe() const override;
    double threshold() const { return threshold_; }

    bool pure() const override { return true; }

private:
    double threshold_;
};

/// True if the ego's speed is strictly below the threshold (m/s).
class SpeedConditionLess : public Condition {
public:
    explicit SpeedConditionLess(double mps);
    traffic::SnapshotColumns columns() const override { return {traffic::SnapshotColumns::Speed}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    std::string describe() const override;
    double threshold() const { return threshold_; }

    bool pure() const override { return true; }

private:
    double threshold_;
};

}  // namespace sbsim::storyboard
