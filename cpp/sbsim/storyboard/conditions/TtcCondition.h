#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/SnapshotStamp.h"
#include "sbsim/storyboard/geometry/Footprint.h"
#include "sbsim/storyboard/geometry/MovingFootprint.h"
#include "sbsim/traffic/PairSweep.h"

namespace sbsim::storyboard {

/// The set of other vehicles within `distance` m (position to position, inclusive) that the ego
/// would hit within `ttc` seconds if both kept driving at constant speed, as in Artery: straight
/// on, or along a circle for a vehicle on a bend. The two footprints are compared at t = i·dt,
/// i = 1..ceil(ttc/dt), with dt the shorter of length/speed of the two (a standing vehicle does not
/// count), so consecutive samples leave no gap. Touching counts as hitting; two standing vehicles
/// never conflict. The work per pair is bounded whatever the ttc: driving straight, two vehicles
/// at the same velocity are tested once and a long run of candidate samples at its ends and
/// middle (the overlapping samples form one run); on a bend at most kMaxBendSamples samples are
/// tested (with dt = length/speed, a thousand samples look minutes ahead: 0.36 s for 5 m at 50 km/h), and the
/// loop gives up when the run is asked to stop (kernel::StopRequest).
///
/// A vehicle's bend is the curvature geometry::PathCurvature finds between its pose in the
/// previous snapshot this condition saw and its pose now (none in its first step); its
/// footprint's centre then follows the circle of that curvature, the heading turning with it.
class TtcCondition : public Condition {
public:
    /// The most samples a pair on a bend is tested at.
    static constexpr std::int64_t kMaxBendSamples = 1'000;

    /// Throws std::invalid_argument unless ttc > 0 and distance >= 0, both finite.
    explicit TtcCondition(double ttc, double distance = 100);

    traffic::SnapshotColumns columns() const override {
        return {traffic::SnapshotColumns::Position, traffic::SnapshotColumns::Speed, traffic::SnapshotColumns::Angle,
                traffic::SnapshotColumns::Size};
    }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void prepare(const EvaluationContext& ctx) override;
    void forget(std::string_view vehicleId) override;
    std::size_t heldVehicles() const override;
    std::optional<double> neighbourRadius() const override { return distance_; }

    std::string describe() const override;
    double ttc() const { return ttc_; }
    double distance() const { return distance_; }

    /// Whether `a` at `speedA` and `b` at `speedB` (m/s, along their headings) overlap at one of
    /// the sample times above. Equal to testing every sample, but only the samples near the time
    /// interval where the moving rectangles can overlap (found per separating axis) are tested
    /// (when both drive straight; with a bend, the samples after the two could first meet).
    static bool conflict(const geometry::Footprint& a, double speedA, const geometry::Footprint& b, double speedB,
                         double ttc);
    static bool conflict(const geometry::MovingFootprint& a, const geometry::MovingFootprint& b, double ttc);
    /// False only for pairs whose bounding circles cannot meet before the last sample: then
    /// conflict() is false as well.
    static bool mayConflict(const geometry::MovingCircle& a, const geometry::MovingCircle& b, double ttc);

    /// test() keeps no state; prepare() keeps the poses for the next step's curvatures and, when
    /// test() asked about most vehicles in the step before and a worker pool is at hand, tests
    /// every pair once ahead (the pair test is symmetric), so test() only looks its answer up.
    bool pure() const override { return true; }

    /// Whether the last prepare() tested the pairs ahead.
    bool pairsTestedAhead() const { return pairsReady_; }

    /// The curvature (1/m) vehicle `i` of the last prepared snapshot is predicted to drive on.
    double curvature(VehicleIndex i) const { return movers_[static_cast<std::size_t>(i)].curvature; }

private:
    /// conflict() for a pair that passed mayConflict(): the samples near the possible overlap.
    static bool sampledConflict(const geometry::MovingFootprint& a, const geometry::MovingFootprint& b, double ttc);
    /// sampledConflict() when one of the two is on a bend.
    static bool sampledCurvedConflict(const geometry::MovingFootprint& a, const geometry::MovingFootprint& b,
                                      double ttc);
    /// conflict() for vehicles `a` and `b` of the prepared step.
    bool conflicts(VehicleIndex a, VehicleIndex b) const;
    /// The step's movers and poses; on the pool when one is given.
    void computeMovers(const traffic::VehicleSnapshot& snapshot, kernel::ParallelFor* parallel);
    /// Every pair within distance_ tested once, on the pool (one sweep of the pairs, a row of
    /// cells per task); fills pairStart_ and pairOthers_.
    void computePairs(const EvaluationContext& ctx);

    /// The front bumper poses of one snapshot, by vehicle id in ascending order.
    struct Poses {
        std::vector<std::string> ids;
        std::vector<Eigen::Vector2d> fronts;
        std::vector<double> angles;    // SUMO degrees
        std::uint64_t idsVersion = 0;  // VehicleSnapshot::idsVersion() of `ids`; 0: none (edited)
        void erase(std::string_view id);
    };

    double ttc_;
    double distance_;
    SnapshotStamp stamp_;
    std::vector<geometry::MovingFootprint> movers_;  // per vehicle of the step
    std::vector<geometry::MovingCircle> circles_;    // the same, compact
    // Pairs tested ahead: vehicle i's others are pairOthers_[pairStart_[i], pairStart_[i + 1]),
    // ascending. rowConflicts_[k] holds the conflicting pairs (smaller index first) the sweep's
    // row k found (one writer per row).
    bool pairsReady_ = false;
    std::vector<std::int32_t> pairStart_;
    std::vector<VehicleIndex> pairOthers_;
    traffic::PairSweep sweep_;
    std::vector<std::vector<std::pair<VehicleIndex, VehicleIndex>>> rowConflicts_;
    std::vector<std::pair<VehicleIndex, VehicleIndex>> conflicting_;
    std::atomic<std::size_t> tests_{0};  // test() calls since the last prepare()
    // The poses of the last snapshot seen and of the one before it (an earlier time): a snapshot
    // seen again at the same time compares with the same previous poses.
    std::optional<kernel::SimTime> currentTime_;
    Poses current_;
    Poses previous_;
};

}  // namespace sbsim::storyboard
