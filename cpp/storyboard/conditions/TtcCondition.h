#pragma once

#include <optional>
#include <vector>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/SnapshotStamp.h"
#include "sbsim/storyboard/geometry/Footprint.h"
#include "sbsim/storyboard/geometry/MovingFootprint.h"

namespace sbsim::storyboard {

/// The set of other vehicles within `distance` m (position to position, inclusive) that the ego
/// would hit within `ttc` seconds if both kept driving straight at constant speed (Artery's
/// straight-line case): the two footprints are compared at t = i·dt, i = 1..ceil(ttc/dt), with dt the
/// shorter of length/speed of the two (a standing vehicle does not count), so consecutive samples
/// leave no gap. Touching counts as hitting; two standing vehicles never conflict.
class TtcCondition : public Condition {
public:
    /// Throws std::invalid_argument unless ttc > 0 and distance >= 0, both finite.
    explicit TtcCondition(double ttc, double distance = 100);

    traffic::SnapshotColumns columns() const override {
        return {traffic::SnapshotColumns::Position, traffic::SnapshotColumns::Speed, traffic::SnapshotColumns::Angle,
                traffic::SnapshotColumns::Size};
    }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void prepare(const EvaluationContext& ctx) override;
    std::optional<double> neighbourRadius() const override { return distance_; }

    double ttc() const { return ttc_; }
    double distance() const { return distance_; }

    /// Whether `a` at `speedA` and `b` at `speedB` (m/s, along their headings) overlap at one of
    /// the sample times above. Equal to testing every sample, but only the samples near the time
    /// interval where the moving rectangles can overlap (found per separating axis) are tested.
    static bool conflict(const geometry::Footprint& a, double speedA, const geometry::Footprint& b, double speedB,
                         double ttc);
    static bool conflict(const geometry::MovingFootprint& a, const geometry::MovingFootprint& b, double ttc);
    /// False only for pairs whose bounding circles cannot meet before the last sample: then
    /// conflict() is false as well.
    static bool mayConflict(const geometry::MovingCircle& a, const geometry::MovingCircle& b, double ttc);

    bool pure() const override { return true; }

private:
    /// conflict() for a pair that passed mayConflict(): the samples near the possible overlap.
    static bool sampledConflict(const geometry::MovingFootprint& a, const geometry::MovingFootprint& b, double ttc);
    void computeMovers(const traffic::VehicleSnapshot& snapshot);

    double ttc_;
    double distance_;
    SnapshotStamp stamp_;
    std::vector<geometry::MovingFootprint> movers_;  // per vehicle of the step
    std::vector<geometry::MovingCircle> circles_;    // the same, compact
};

}  // namespace sbsim::storyboard
