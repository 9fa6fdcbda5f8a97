#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/SnapshotStamp.h"
#include "sbsim/traffic/PairSweep.h"

namespace sbsim::storyboard {

/// Common part of SpeedDifferenceConditionFaster/Slower: the set of other vehicles whose speed
/// differs from the ego's by more than `delta` (m/s, strict) in the given direction, optionally only
/// those within `distance` m (inclusive, through the neighbour grid).
class SpeedDifferenceCondition : public Condition {
public:
    traffic::SnapshotColumns columns() const override {
        return {traffic::SnapshotColumns::Position, traffic::SnapshotColumns::Speed};
    }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void prepare(const EvaluationContext& ctx) override;
    std::optional<double> neighbourRadius() const override { return distance_; }

    std::string describe() const override;
    double delta() const { return delta_; }
    std::optional<double> distance() const { return distance_; }
    /// Whether the last prepare() found every vehicle's answer ahead (with a distance and a pool,
    /// when test() asked about most vehicles in the step before).
    bool answersAhead() const { return answersReady_; }

protected:
    enum class Direction { EgoFaster, EgoSlower };
    /// Throws std::invalid_argument for a NaN delta or a negative or non-finite distance.
    SpeedDifferenceCondition(Direction direction, double delta, std::optional<double> distance);

    bool pure() const override { return true; }

private:
    bool qualifies(double egoSpeed, double otherSpeed) const {
        return direction_ == Direction::EgoFaster ? egoSpeed - otherSpeed > delta_ : otherSpeed - egoSpeed > delta_;
    }
    ConditionResult testAll(const traffic::VehicleSnapshot& snapshot, VehicleIndex ego);
    void sortBySpeed(const traffic::VehicleSnapshot& snapshot);
    /// With a distance: every vehicle's answer at once, from one sweep of the pairs within the
    /// distance (each pair's distance tested once), on the pool; fills answerStart_ and answerOthers_.
    void computeAnswers(const EvaluationContext& ctx);

    Direction direction_;
    double delta_;
    std::optional<double> distance_;
    // Per step, without a distance: all vehicles by ascending speed, so the qualifying ones are a
    // prefix (ego faster) or a suffix (ego slower) found by binary search.
    SnapshotStamp stamp_;  // the snapshot the per-step values below were made for
    std::vector<VehicleIndex> bySpeed_;
    std::vector<double> sortedSpeeds_;
    // Per step, with a distance: the lowest and highest speed of the snapshot stamp_ names.
    double lowestSpeed_ = 0;
    double highestSpeed_ = 0;
    // With a distance and a pool, when test() asked about most vehicles in the step before (as
    // TtcCondition does): vehicle i's answer is answerOthers_[answerStart_[i], answerStart_[i + 1]),
    // ascending, for the snapshot stamp_ names. rowFound_[k]: the (ego, other) the sweep's row k found.
    bool answersReady_ = false;
    std::atomic<std::size_t> tests_{0};  // test() calls since the last prepare()
    std::size_t preparedSize_ = 0;       // vehicles at the last prepare()
    std::vector<std::int32_t> answerStart_;
    std::vector<VehicleIndex> answerOthers_;
    traffic::PairSweep sweep_;
    std::vector<std::vector<std::pair<VehicleIndex, VehicleIndex>>> rowFound_;
    std::vector<std::pair<VehicleIndex, VehicleIndex>> found_;
};

/// The other vehicles the ego is faster than by more than `delta`: speed(ego) - speed(o) > delta.
class SpeedDifferenceConditionFaster : public SpeedDifferenceCondition {
public:
    explicit SpeedDifferenceConditionFaster(double delta, std::optional<double> distance = std::nullopt)
        : SpeedDifferenceCondition(Direction::EgoFaster, delta, distance) {}
};

/// The other vehicles the ego is slower than by more than `delta`: speed(o) - speed(ego) > delta.
class SpeedDifferenceConditionSlower : public SpeedDifferenceCondition {
public:
    explicit SpeedDifferenceConditionSlower(double delta, std::optional<double> distance = std::nullopt)
        : SpeedDifferenceCondition(Direction::EgoSlower, delta, distance) {}
};

}  // namespace sbsim::storyboard
