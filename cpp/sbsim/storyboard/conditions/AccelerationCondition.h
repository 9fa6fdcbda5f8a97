#pragma once

#include "sbsim/storyboard/Condition.h"

namespace sbsim::storyboard {

/// True if the ego's acceleration (m/s², braking is negative) is strictly above the threshold.
class AccelerationConditionGreater : public Condition {
public:
    /// Throws std::invalid_argument for a NaN threshold.
    explicit AccelerationConditionGreater(double threshold);
    traffic::SnapshotColumns columns() const override { return {traffic::SnapshotColumns::Acceleration}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override {
        return ctx.snapshot().accelerations()[ego] > threshold_;
    }
    bool pure() const override { return true; }
    std::string describe() const override;
    double threshold() const { return threshold_; }

private:
    double threshold_;
};

/// True if the ego's acceleration (m/s², braking is negative) is strictly below the threshold.
class AccelerationConditionLess : public Condition {
public:
    /// Throws std::invalid_argument for a NaN threshold.
    explicit AccelerationConditionLess(double threshold);
    traffic::SnapshotColumns columns() const override { return {traffic::SnapshotColumns::Acceleration}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override {
        return ctx.snapshot().accelerations()[ego] < threshold_;
    }
    bool pure() const override { return true; }
    std::string describe() const override;
    double threshold() const { return threshold_; }

private:
    double threshold_;
};

}  // namespace sbsim::storyboard
