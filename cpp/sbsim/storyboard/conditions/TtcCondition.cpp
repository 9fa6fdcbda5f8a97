#include "sbsim/storyboard/conditions/TtcCondition.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "sbsim/kernel/StopRequest.h"
#include "sbsim/storyboard/geometry/PathCurvature.h"

namespace sbsim::storyboard {

using geometry::Footprint;
using geometry::MovingCircle;
using geometry::MovingFootprint;

namespace {
/// Samples tested at each end of a long straight candidate range (see sampledConflict).
constexpr std::int64_t kEdgeSamples = 64;
/// How often a long sampling loop looks whether the run was asked to stop.
constexpr std::int64_t kStopCheckEvery = 4096;
}  // namespace

TtcCondition::TtcCondition(double ttc, double distance) : ttc_(ttc), distance_(distance) {
    if (!(ttc_ > 0 && std::isfinite(ttc_))) {
        throw std::invalid_argument(fmt::format("TtcCondition: ttc must be finite and > 0, not {:f}", ttc_));
    }
    if (!(distance_ >= 0 && std::isfinite(distance_))) {
        throw std::invalid_argument(fmt::format("TtcCondition: distance must be finite and >= 0, not {:f}", distance_));
    }
}

void TtcCondition::prepare(const EvaluationContext& ctx) {
    const std::size_t before = movers_.size();
    computeMovers(ctx.snapshot(), ctx.parallel());
    // Pairs ahead only pay when test() will ask about most vehicles, as it did last step: a story
    // whose other conditions fail first (a time window, an area) asks about few or none.
    const std::size_t asked = tests_.exchange(0, std::memory_order_relaxed);
    if (ctx.parallel() != nullptr && before > 0 && 2 * asked >= before) computePairs(ctx);
}

void TtcCondition::computePairs(const EvaluationContext& ctx) {
    const std::size_t n = movers_.size();
    // One sweep visits each pair within distance_ once (a search per vehicle meets it twice);
    // a pair is tested with its smaller index first, as the search per vehicle does.
    sweep_.build(ctx.snapshot(), distance_);
    // Few pairs conflict: sorted, they are each vehicle's later conflicts in ascending order.
    sweep_.collectSorted(*ctx.parallel(), rowConflicts_, conflicting_, [&](VehicleIndex a, VehicleIndex b, auto& out) {
        const VehicleIndex ego = std::min(a, b);
        const VehicleIndex other = std::max(a, b);
        if (conflicts(ego, other)) out.emplace_back(ego, other);
    });
    // Each pair counts for both vehicles. Walking the pairs in ascending order appends to
    // vehicle j first the smaller indices that found it, then its own larger ones: ascending.
    pairStart_.assign(n + 1, 0);
    for (const auto& [k, o] : conflicting_) {
        ++pairStart_[static_cast<std::size_t>(k) + 1];
        ++pairStart_[static_cast<std::size_t>(o) + 1];
    }
    for (std::size_t k = 0; k < n; ++k) pairStart_[k + 1] += pairStart_[k];
    pairOthers_.resize(static_cast<std::size_t>(pairStart_[n]));
    std::vector<std::int32_t> next(pairStart_.begin(), pairStart_.end() - 1);
    for (const auto& [k, o] : conflicting_) {
        pairOthers_[static_cast<std::size_t>(next[static_cast<std::size_t>(k)]++)] = o;
        pairOthers_[static_cast<std::size_t>(next[static_cast<std::size_t>(o)]++)] = k;
    }
    pairsReady_ = true;
}

void TtcCondition::Poses::erase(std::string_view id) {
    const auto it = std::lower_bound(ids.begin(), ids.end(), id);
    if (it == ids.end() || *it != id) return;
    const auto k = it - ids.begin();
    ids.erase(it);
    idsVersion = 0;  // no snapshot's ids any more
    fronts.erase(fronts.begin() + k);
    angles.erase(angles.begin() + k);
}

void TtcCondition::forget(std::string_view vehicleId) {
    current_.erase(vehicleId);
    previous_.erase(vehicleId);
}

std::size_t TtcCondition::heldVehicles() const { return std::max(current_.ids.size(), previous_.ids.size()); }

void TtcCondition::computeMovers(const traffic::VehicleSnapshot& snapshot, kernel::ParallelFor* parallel) {
    if (currentTime_ != snapshot.time()) {
        std::swap(previous_, current_);
        currentTime_ = snapshot.time();
    }
    pairsReady_ = false;
    const auto count = static_cast<std::size_t>(snapshot.size());
    const std::vector<std::string>& ids = snapshot.ids();
    current_.ids.resize(count);
    current_.fronts.resize(count);
    current_.angles.resize(count);
    const MovingFootprint standing(Footprint(Eigen::Vector2d::Zero(), Eigen::Vector2d::UnitX(), 0, 0), 0);
    movers_.resize(count, standing);  // every element is overwritten below
    circles_.resize(count);
    // The same vehicles as in the poses kept (no vehicle came or went): their ids need no copy,
    // and each vehicle's previous pose is at its own index.
    const std::uint64_t version = snapshot.idsVersion();
    const bool copyIds = current_.idsVersion != version;
    const bool sameAsBefore = previous_.idsVersion == version && previous_.ids.size() == count;
    const auto body = [&](std::size_t begin, std::size_t end) {
        // Otherwise both id lists ascend: one merge pass per chunk finds each vehicle's previous pose.
        if (begin == end) return;
        const auto& before = previous_.ids;
        auto p =
            sameAsBefore
                ? begin
                : static_cast<std::size_t>(std::lower_bound(before.begin(), before.end(), ids[begin]) - before.begin());
        for (std::size_t k = begin; k < end; ++k) {
            const auto i = static_cast<VehicleIndex>(k);
            const Eigen::Vector2d front = snapshot.positions().col(i);
            const double angle = snapshot.angles()[i];
            const double speed = snapshot.speeds()[i];
            if (copyIds && current_.ids[k] != ids[k]) current_.ids[k] = ids[k];  // most ids keep their slot
            current_.fronts[k] = front;
            current_.angles[k] = angle;
            bool seen = sameAsBefore;
            if (sameAsBefore) {
                p = k;
            } else {
                while (p < before.size() && before[p] < ids[k]) ++p;
                seen = p < before.size() && before[p] == ids[k];
            }
            const double curvature =
                seen ? geometry::PathCurvature::of(previous_.fronts[p], previous_.angles[p], front, angle, speed) : 0.0;
            movers_[k] = MovingFootprint(Footprint::fromSumo(front, angle, snapshot.lengths()[i], snapshot.widths()[i]),
                                         speed, curvature);
            circles_[k] = movers_[k].circle;
        }
    };
    if (parallel != nullptr) {
        parallel->run(count, body, 256);
    } else {
        body(0, count);
    }
    current_.idsVersion = version;
    stamp_ = SnapshotStamp::of(snapshot);
}

ConditionResult TtcCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const traffic::VehicleSnapshot& snapshot = ctx.snapshot();
    tests_.fetch_add(1, std::memory_order_relaxed);
    if (!(stamp_ == SnapshotStamp::of(snapshot))) computeMovers(snapshot, nullptr);
    if (pairsReady_) {
        const auto k = static_cast<std::size_t>(ego);
        return ConditionResult::ofOthers(
            std::vector<VehicleIndex>(pairOthers_.begin() + pairStart_[k], pairOthers_.begin() + pairStart_[k + 1]));
    }
    std::vector<VehicleIndex> others;  // local: test() may run on several threads at once
    ctx.neighbours().forEachWithin(ego, distance_, [&](VehicleIndex o) {
        if (conflicts(ego, o)) others.push_back(o);
    });
    std::sort(others.begin(), others.end());
    return ConditionResult::ofOthers(std::move(others));
}

bool TtcCondition::conflicts(VehicleIndex a, VehicleIndex b) const {
    // The compact circles first: the full footprints are read for the few pairs that may meet.
    const auto i = static_cast<std::size_t>(a);
    const auto j = static_cast<std::size_t>(b);
    return mayConflict(circles_[i], circles_[j], ttc_) && sampledConflict(movers_[i], movers_[j], ttc_);
}

bool TtcCondition::conflict(const Footprint& a, double speedA, const Footprint& b, double speedB, double ttc) {
    return conflict(MovingFootprint(a, speedA), MovingFootprint(b, speedB), ttc);
}

bool TtcCondition::mayConflict(const MovingCircle& a, const MovingCircle& b, double ttc) {
    // Beyond the last sample time, ceil(ttc/dt)·dt < ttc + dt: the circles must meet before that.
    const double dt = std::min(a.sampleStep, b.sampleStep);
    if (!(dt > 0 && std::isfinite(dt)) || !(ttc > 0)) return false;  // both standing, or zero length
    const double horizon = (ttc + dt) * (1 + 1e-12);
    if (a.curvature == 0 && b.curvature == 0) return mayMeet(a, b, horizon);
    // On a bend a centre still stays within speed·t of where it starts (an arc is no shorter
    // than its chord).
    const double reach = a.radius + b.radius + 1e-4 + (a.velocity.norm() + b.velocity.norm()) * horizon;
    return !((b.centre - a.centre).squaredNorm() > reach * reach);
}

bool TtcCondition::conflict(const MovingFootprint& ma, const MovingFootprint& mb, double ttc) {
    // Cheap first: most neighbour pairs end here (same direction, moving apart, passing wide).
    return mayConflict(ma.circle, mb.circle, ttc) && sampledConflict(ma, mb, ttc);
}

bool TtcCondition::sampledConflict(const MovingFootprint& ma, const MovingFootprint& mb, double ttc) {
    if (std::isnan(ma.speed) || std::isnan(mb.speed)) return false;
    if (ma.curvature != 0 || mb.curvature != 0) return sampledCurvedConflict(ma, mb, ttc);
    const Footprint& a = ma.footprint;
    const Footprint& b = mb.footprint;
    const double dt = std::min(ma.circle.sampleStep, mb.circle.sampleStep);
    // Centre offset d(t) = d0 + w t.
    const Eigen::Vector2d d0 = b.centre() - a.centre();
    const Eigen::Vector2d w = mb.circle.velocity - ma.circle.velocity;
    const double lastStep = std::min(std::ceil(ttc / dt), 1e15);
    const double horizon = lastStep * dt;
    const double margin = 1e-6 + 1e-9 * (d0.lpNorm<Eigen::Infinity>() + w.lpNorm<Eigen::Infinity>() * horizon);

    // On each separating axis the projected gap is linear in t, so the rectangles can overlap
    // only in the intersection of four time intervals; only samples in it are tested.
    double from = -std::numeric_limits<double>::infinity();
    double to = std::numeric_limits<double>::infinity();
    const auto window = [&](double slack, double& lo, double& hi) {
        lo = -std::numeric_limits<double>::infinity();
        hi = std::numeric_limits<double>::infinity();
        for (const Eigen::Vector2d& axis : {a.heading(), a.right(), b.heading(), b.right()}) {
            const double reach = geometry::projectedHalfExtent(a, axis) + geometry::projectedHalfExtent(b, axis) +
                                 Footprint::kTouchTolerance + slack;
            const double s0 = d0.dot(axis);
            const double ds = w.dot(axis);
            if (ds == 0) {
                if (std::abs(s0) > reach) return false;  // separated on this axis forever
                continue;
            }
            double t1 = (-reach - s0) / ds;
            double t2 = (reach - s0) / ds;
            if (t1 > t2) std::swap(t1, t2);
            lo = std::max(lo, t1);
            hi = std::min(hi, t2);
        }
        return true;
    };
    if (!window(margin, from, to)) return false;
    if (!(from <= to)) return false;

    const double firstCandidate = std::max(1.0, std::floor(from / dt));
    const double lastCandidate = std::min(lastStep, std::ceil(to / dt));
    if (!(firstCandidate <= lastCandidate)) return false;
    const auto first = static_cast<std::int64_t>(firstCandidate);
    const auto last = static_cast<std::int64_t>(lastCandidate);
    const auto overlapsAt = [&](std::int64_t i) {
        const double t = static_cast<double>(i) * dt;
        return overlaps(a.movedFor(ma.speed, t), b.movedFor(mb.speed, t));
    };
    // The same velocity: the offset never changes, one sample decides for all of them.
    if (w.isZero()) return overlapsAt(first);
    // The four axes separate two rectangles exactly, so the overlapping samples are one run: a
    // long range of candidates (a huge ttc, whose margin above grows with it, or two vehicles at
    // nearly the same velocity) is tested at both ends, then at the middle of the samples in the
    // window without the horizon's margin, which lies deep inside the run if there is one. The
    // work per pair is bounded whatever the ttc.
    if (last - first > 2 * kEdgeSamples) {
        for (std::int64_t k = 0; k < kEdgeSamples; ++k) {
            if (overlapsAt(first + k) || overlapsAt(last - k)) return true;
        }
        double lo = 0;
        double hi = 0;
        if (!window(1e-6 + 1e-9 * d0.lpNorm<Eigen::Infinity>(), lo, hi)) return false;
        const double innerFirst = std::max(firstCandidate, std::ceil(lo / dt));
        const double innerLast = std::min(lastCandidate, std::floor(hi / dt));
        if (!(innerFirst <= innerLast)) return false;
        return overlapsAt(static_cast<std::int64_t>(innerFirst + std::floor((innerLast - innerFirst) / 2)));
    }
    for (std::int64_t i = first; i <= last; ++i) {
        if (overlapsAt(i)) return true;
    }
    return false;
}

bool TtcCondition::sampledCurvedConflict(const MovingFootprint& ma, const MovingFootprint& mb, double ttc) {
    const double dt = std::min(ma.circle.sampleStep, mb.circle.sampleStep);
    const double lastStep = std::min(std::ceil(ttc / dt), 1e15);
    // The centres close in by at most the sum of the speeds (chord <= arc): the samples before
    // the holding circles can first touch are skipped; each later one is tested circle first.
    const double reach = ma.circle.radius + mb.circle.radius + 1e-4;
    const double closing = std::abs(ma.speed) + std::abs(mb.speed);
    const double gap = (mb.footprint.centre() - ma.footprint.centre()).norm() - reach;
    const double firstCandidate = std::max(1.0, std::floor(gap / closing / dt));
    if (!(firstCandidate <= lastStep)) return false;
    const auto first = static_cast<std::int64_t>(firstCandidate);
    // A bend is followed for kMaxBendSamples samples at most: circles never part, so nothing else
    // ends the loop for a huge ttc.
    const auto last = std::min(static_cast<std::int64_t>(lastStep), first + kMaxBendSamples - 1);
    for (std::int64_t i = first; i <= last; ++i) {
        if ((i - first) % kStopCheckEvery == kStopCheckEvery - 1 && kernel::StopRequest::requested()) return false;
        const double t = static_cast<double>(i) * dt;
        // The centres first (no cosine): most samples end at the holding circles.
        if ((mb.centreAt(t) - ma.centreAt(t)).squaredNorm() > reach * reach) continue;
        if (overlaps(ma.at(t), mb.at(t))) return true;
    }
    return false;
}

std::string TtcCondition::describe() const {
    return fmt::format("TtcCondition({:g} s, within {:g} m)", ttc_, distance_);
}

}  // namespace sbsim::storyboard
