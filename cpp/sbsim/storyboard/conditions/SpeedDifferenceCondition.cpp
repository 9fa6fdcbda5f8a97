#include "sbsim/storyboard/conditions/SpeedDifferenceCondition.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace sbsim::storyboard {

SpeedDifferenceCondition::SpeedDifferenceCondition(Direction direction, double delta, std::optional<double> distance)
    : direction_(direction), delta_(delta), distance_(distance) {
    if (std::isnan(delta_)) throw std::invalid_argument("SpeedDifferenceCondition: delta must not be NaN");
    if (distance_ && !(*distance_ >= 0 && std::isfinite(*distance_))) {
        throw std::invalid_argument(
            fmt::format("SpeedDifferenceCondition: distance must be finite and >= 0, not {:f}", *distance_));
    }
}

void SpeedDifferenceCondition::prepare(const EvaluationContext& ctx) {
    if (!distance_) {
        sortBySpeed(ctx.snapshot());
        return;
    }
    // The step's extreme speeds (NaN skipped: it qualifies for nothing): an ego no other vehicle
    // can differ from by more than delta needs no neighbour search.
    const Eigen::VectorXd& speeds = ctx.snapshot().speeds();
    double low = std::numeric_limits<double>::infinity();
    double high = -std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < ctx.snapshot().size(); ++i) {
        const double v = speeds[i];
        if (v < low) low = v;
        if (v > high) high = v;
    }
    lowestSpeed_ = low;
    highestSpeed_ = high;
    stamp_ = SnapshotStamp::of(ctx.snapshot());
    // All answers ahead only pay when test() will ask about most vehicles, as it did last step: a
    // story whose other conditions fail first (a time window, an area) asks about few or none.
    answersReady_ = false;
    const std::size_t before = preparedSize_;
    preparedSize_ = static_cast<std::size_t>(ctx.snapshot().size());
    const std::size_t asked = tests_.exchange(0, std::memory_order_relaxed);
    if (ctx.parallel() != nullptr && before > 0 && 2 * asked >= before) computeAnswers(ctx);
}

void SpeedDifferenceCondition::computeAnswers(const EvaluationContext& ctx) {
    const traffic::VehicleSnapshot& snapshot = ctx.snapshot();
    const auto n = static_cast<std::size_t>(snapshot.size());
    const Eigen::VectorXd& speeds = snapshot.speeds();
    sweep_.build(snapshot, *distance_);
    // Sorted by ego, then other: each ego's answer is one ascending run.
    sweep_.collectSorted(*ctx.parallel(), rowFound_, found_, [&](VehicleIndex a, VehicleIndex b, auto& out) {
        if (qualifies(speeds[a], speeds[b])) out.emplace_back(a, b);
        if (qualifies(speeds[b], speeds[a])) out.emplace_back(b, a);
    });
    answerStart_.assign(n + 1, 0);
    for (const auto& [ego, other] : found_) ++answerStart_[static_cast<std::size_t>(ego) + 1];
    for (std::size_t k = 0; k < n; ++k) answerStart_[k + 1] += answerStart_[k];
    answerOthers_.resize(found_.size());
    for (std::size_t k = 0; k < found_.size(); ++k) answerOthers_[k] = found_[k].second;
    answersReady_ = true;
}

void SpeedDifferenceCondition::sortBySpeed(const traffic::VehicleSnapshot& snapshot) {
    const Eigen::VectorXd& speeds = snapshot.speeds();
    bySpeed_.resize(static_cast<std::size_t>(snapshot.size()));
    std::iota(bySpeed_.begin(), bySpeed_.end(), VehicleIndex{0});
    std::sort(bySpeed_.begin(), bySpeed_.end(), [&](VehicleIndex a, VehicleIndex b) { return speeds[a] < speeds[b]; });
    sortedSpeeds_.resize(bySpeed_.size());
    for (std::size_t k = 0; k < bySpeed_.size(); ++k) sortedSpeeds_[k] = speeds[bySpeed_[k]];
    stamp_ = SnapshotStamp::of(snapshot);
}

ConditionResult SpeedDifferenceCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const traffic::VehicleSnapshot& snapshot = ctx.snapshot();
    if (!distance_) return testAll(snapshot, ego);
    tests_.fetch_add(1, std::memory_order_relaxed);
    const Eigen::VectorXd& speeds = snapshot.speeds();
    const double egoSpeed = speeds[ego];
    const bool prepared = stamp_ == SnapshotStamp::of(snapshot);
    // Rounded subtraction is monotone, so if the step's fastest (slowest) vehicle does not
    // qualify, none does. Only with the extremes of this very snapshot (prepare()'s).
    if (prepared && !qualifies(egoSpeed, highestSpeed_) && !qualifies(egoSpeed, lowestSpeed_)) {
        return ConditionResult::ofOthers({});
    }
    if (prepared && answersReady_) {
        const auto k = static_cast<std::size_t>(ego);
        return ConditionResult::ofOthers(std::vector<VehicleIndex>(answerOthers_.begin() + answerStart_[k],
                                                                   answerOthers_.begin() + answerStart_[k + 1]));
    }
    std::vector<VehicleIndex> others;  // local: test() may run on several threads at once
    ctx.neighbours().forEachWithin(ego, *distance_, [&](VehicleIndex o) {
        if (qualifies(egoSpeed, speeds[o])) others.push_back(o);
    });
    std::sort(others.begin(), others.end());
    return ConditionResult::ofOthers(std::move(others));
}

ConditionResult SpeedDifferenceCondition::testAll(const traffic::VehicleSnapshot& snapshot, VehicleIndex ego) {
    if (!(stamp_ == SnapshotStamp::of(snapshot))) sortBySpeed(snapshot);
    const Eigen::VectorXd& speeds = snapshot.speeds();
    const double egoSpeed = speeds[ego];
    // The exact predicate is monotone in the other's speed (rounded subtraction is monotone), so
    // the qualifying vehicles form one run of the speed order.
    auto first = sortedSpeeds_.begin();
    auto last = sortedSpeeds_.end();
    if (direction_ == Direction::EgoFaster) {
        last = std::partition_point(first, last, [&](double s) { return qualifies(egoSpeed, s); });
    } else {
        first = std::partition_point(first, last, [&](double s) { return !qualifies(egoSpeed, s); });
    }
    const auto count = static_cast<std::size_t>(last - first);
    if (count == 0) return ConditionResult::ofOthers({});

    std::vector<VehicleIndex> others;
    if (count > bySpeed_.size() / 16) {
        // Many matches: a scan in index order is cheaper than sorting them and is already sorted.
        others.reserve(count);
        for (VehicleIndex o = 0; o < snapshot.size(); ++o) {
            if (o != ego && qualifies(egoSpeed, speeds[o])) others.push_back(o);
        }
        return ConditionResult::ofOthers(std::move(others));
    }
    const auto offset = first - sortedSpeeds_.begin();
    others.reserve(count);
    for (auto it = bySpeed_.begin() + offset, end = it + static_cast<std::ptrdiff_t>(count); it != end; ++it) {
        if (*it != ego) others.push_back(*it);
    }
    std::sort(others.begin(), others.end());
    return ConditionResult::ofOthers(std::move(others));
}

std::string SpeedDifferenceCondition::describe() const {
    return fmt::format("SpeedDifferenceCondition{}({:g} m/s{})",
                       direction_ == Direction::EgoFaster ? "Faster" : "Slower", delta_,
                       distance_ ? fmt::format(", within {:g} m", *distance_) : "");
}

}  // namespace sbsim::storyboard
