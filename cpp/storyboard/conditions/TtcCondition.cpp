#include "storyboard/conditions/TtcCondition.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace sbsim::storyboard {

using geometry::Footprint;

TtcCondition::TtcCondition(double ttc, double distance) : ttc_(ttc), distance_(distance) {
    if (!(ttc_ > 0 && std::isfinite(ttc_))) {
        throw std::invalid_argument("TtcCondition: ttc must be finite and > 0, not " + std::to_string(ttc_));
    }
    if (!(distance_ >= 0 && std::isfinite(distance_))) {
        throw std::invalid_argument("TtcCondition: distance must be finite and >= 0, not " + std::to_string(distance_));
    }
}

void TtcCondition::prepare(const EvaluationContext& ctx) { computeFootprints(ctx.snapshot()); }

void TtcCondition::computeFootprints(const traffic::VehicleSnapshot& snapshot) {
    const VehicleIndex n = snapshot.size();
    footprints_.clear();
    footprints_.reserve(static_cast<std::size_t>(n));
    for (VehicleIndex i = 0; i < n; ++i) {
        footprints_.push_back(Footprint::fromSumo(snapshot.positions().col(i), snapshot.angles()[i],
                                                  snapshot.lengths()[i], snapshot.widths()[i]));
    }
    stamp_ = SnapshotStamp::of(snapshot);
}

ConditionResult TtcCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const traffic::VehicleSnapshot& snapshot = ctx.snapshot();
    if (!(stamp_ == SnapshotStamp::of(snapshot))) computeFootprints(snapshot);
    const Eigen::VectorXd& speeds = snapshot.speeds();
    const Footprint& egoFootprint = footprints_[ego];
    const double egoSpeed = speeds[ego];
    std::vector<VehicleIndex> others;  // local: test() may run on several threads at once
    ctx.neighbours().forEachWithin(ego, distance_, [&](VehicleIndex o) {
        if (conflict(egoFootprint, egoSpeed, footprints_[o], speeds[o], ttc_)) others.push_back(o);
    });
    std::sort(others.begin(), others.end());
    return ConditionResult::ofOthers(std::move(others));
}

bool TtcCondition::conflict(const Footprint& a, double speedA, const Footprint& b, double speedB, double ttc) {
    if (std::isnan(speedA) || std::isnan(speedB)) return false;
    double dt = std::numeric_limits<double>::infinity();
    if (speedA != 0) dt = 2 * a.halfLength() / std::abs(speedA);
    if (speedB != 0) dt = std::min(dt, 2 * b.halfLength() / std::abs(speedB));
    if (!(dt > 0 && std::isfinite(dt)) || !(ttc > 0)) return false;  // both standing, or zero length
    const double lastStep = std::min(std::ceil(ttc / dt), 1e15);

    // Centre offset d(t) = d0 + w t. On each separating axis the projected gap is linear in t, so
    // the rectangles can overlap only in the intersection of four time intervals. The intervals
    // are widened by a margin far above rounding error; the samples in them are then tested
    // exactly as the plain loop would, so the result is the same.
    constexpr double kMargin = 1e-6;
    const Eigen::Vector2d d0 = b.centre() - a.centre();
    const Eigen::Vector2d w = speedB * b.heading() - speedA * a.heading();
    // Cheap first: circles around both rectangles that cannot meet within the horizon mean the
    // rectangles cannot either (most neighbour pairs end here).
    const double reachAll = std::hypot(a.halfLength(), a.halfWidth()) + std::hypot(b.halfLength(), b.halfWidth()) +
                            Footprint::kTouchTolerance + kMargin + w.norm() * lastStep * dt;
    if (d0.squaredNorm() > reachAll * reachAll) return false;
    double from = -std::numeric_limits<double>::infinity();
    double to = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector2d& axis : {a.heading(), a.right(), b.heading(), b.right()}) {
        const double reach = geometry::projectedHalfExtent(a, axis) + geometry::projectedHalfExtent(b, axis) +
                             Footprint::kTouchTolerance + kMargin;
        const double s0 = d0.dot(axis);
        const double ds = w.dot(axis);
        if (ds == 0) {
            if (std::abs(s0) > reach) return false;  // separated on this axis forever
            continue;
        }
        double t1 = (-reach - s0) / ds;
        double t2 = (reach - s0) / ds;
        if (t1 > t2) std::swap(t1, t2);
        from = std::max(from, t1);
        to = std::min(to, t2);
    }
    if (!(from <= to)) return false;

    const double firstCandidate = std::max(1.0, std::floor(from / dt));
    const double lastCandidate = std::min(lastStep, std::ceil(to / dt));
    if (!(firstCandidate <= lastCandidate)) return false;
    const auto first = static_cast<std::int64_t>(firstCandidate);
    const auto last = static_cast<std::int64_t>(lastCandidate);
    for (std::int64_t i = first; i <= last; ++i) {
        const double t = static_cast<double>(i) * dt;
        if (overlaps(a.movedFor(speedA, t), b.movedFor(speedB, t))) return true;
    }
    return false;
}

}  // namespace sbsim::storyboard
