#include "sbsim/radio/disc/KeptNeighbourhoods.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sbsim::radio {

KeptNeighbourhoods::KeptNeighbourhoods(double radius, double skin)
    : radius_(radius), skin_(skin), reach_(radius + skin) {
    if (!(radius >= 0) || !std::isfinite(radius))
        throw std::invalid_argument("kept neighbourhoods: radius must be >= 0");
    if (!(skin > 0) || !std::isfinite(skin)) throw std::invalid_argument("kept neighbourhoods: skin must be > 0");
}

void KeptNeighbourhoods::update(const Eigen::Matrix2Xd& positions, std::span<const Key> keys, bool idsChanged) {
    positions_ = &positions;
    keys_ = keys;
    ++epochUpdates_;
    const auto n = static_cast<Index>(keys.size());
    if (idsChanged || epochs_ == 0) {
        const Key top = keys.empty() ? 0 : *std::max_element(keys.begin(), keys.end());
        if (keyToCurrent_.size() <= top) {
            keyToCurrent_.resize(top + 1, -1);
            hasReference_.resize(top + 1, 0);
            moved_.resize(top + 1, 0);
            referenceX_.resize(top + 1);
            referenceY_.resize(top + 1);
        }
        std::fill(keyToCurrent_.begin(), keyToCurrent_.end(), -1);
        for (Index i = 0; i < n; ++i) {
            const Key k = keys[static_cast<std::size_t>(i)];
            keyToCurrent_[k] = i;
            if (!hasReference_[k]) {
                // A newcomer: its first position is its reference for the rest of the epoch.
                hasReference_[k] = 1;
                referenceX_[k] = positions(0, i);
                referenceY_[k] = positions(1, i);
                newcomers_.push_back(k);
            }
        }
        for (std::size_t e = 0; e < epochKeys_.size(); ++e) {
            const Key k = epochKeys_[e];
            epochToCurrent_[e] = moved_[k] ? -1 : keyToCurrent_[k];
        }
    }
    if (epochs_ == 0) {
        startEpoch();
        return placeCurrent();
    }
    // A pair (i, j) is within the radius only if its references are within radius + skin while
    // neither moved more than half the skin from its reference. One that did (a fast vehicle, a
    // jump: SUMO's teleports) takes its position as its new reference, as a newcomer: found by the
    // others through the newcomers, its own list made again, no longer found by its old place.
    const double half = skin_ / 2 * (1 - 1e-9) - 1e-9 * reach_;  // a margin far above the rounding
    for (Index i = 0; i < n; ++i) {
        const Key k = keys[static_cast<std::size_t>(i)];
        const double dx = positions(0, i) - referenceX_[k];
        const double dy = positions(1, i) - referenceY_[k];
        if (dx * dx + dy * dy <= half * half) continue;  // NaN: moved
        referenceX_[k] = positions(0, i);
        referenceY_[k] = positions(1, i);
        newcomers_.push_back(k);
        if (k < lists_.size()) lists_[k].epoch = 0;
        if (!moved_[k]) {
            moved_[k] = 1;
            const auto e = std::lower_bound(epochKeysSorted_.begin(), epochKeysSorted_.end(), std::pair{k, Index{0}},
                                            [](const auto& a, const auto& b) { return a.first < b.first; });
            if (e != epochKeysSorted_.end() && e->first == k) epochToCurrent_[static_cast<std::size_t>(e->second)] = -1;
        }
    }
    // Many newcomers make every list's scan of them long: all lists start again.
    if (newcomers_.size() > 64 + static_cast<std::size_t>(n) / 8) startEpoch();
    placeCurrent();
}

void KeptNeighbourhoods::placeCurrent() {
    const Eigen::Matrix2Xd& positions = *positions_;
    const double none = std::numeric_limits<double>::quiet_NaN();  // never within: the test is false
    epochCurrent_.resize(epochToCurrent_.size());
    Index previous = -1;
    ascending_ = true;
    for (std::size_t e = 0; e < epochToCurrent_.size(); ++e) {
        const Index j = epochToCurrent_[e];
        epochCurrent_[e] = j < 0 ? Candidate{none, none, -1} : Candidate{positions(0, j), positions(1, j), j};
        if (j < 0) continue;
        ascending_ = ascending_ && j > previous;
        previous = j;
    }
}

void KeptNeighbourhoods::startEpoch() {
    if (epochs_ > 0) lastEpochUpdates_ = epochUpdates_;
    epochUpdates_ = 0;
    ++epochs_;
    const Eigen::Matrix2Xd& positions = *positions_;
    // Lists of vehicles gone for good are freed; the others are rebuilt when next asked for.
    for (const Key k : epochKeys_) {
        if (keyToCurrent_[k] < 0 && k < lists_.size()) lists_[k] = List{};
    }
    for (const Key k : newcomers_) {
        if (keyToCurrent_[k] < 0 && k < lists_.size()) lists_[k] = List{};
    }
    std::fill(hasReference_.begin(), hasReference_.end(), 0);
    std::fill(moved_.begin(), moved_.end(), 0);
    newcomers_.clear();
    epochPositions_ = positions;
    epochKeys_.assign(keys_.begin(), keys_.end());
    epochToCurrent_.resize(epochKeys_.size());
    epochKeysSorted_.resize(epochKeys_.size());
    for (std::size_t i = 0; i < epochKeys_.size(); ++i) {
        const Key k = epochKeys_[i];
        epochToCurrent_[i] = static_cast<Index>(i);
        epochKeysSorted_[i] = {k, static_cast<Index>(i)};
        hasReference_[k] = 1;
        referenceX_[k] = positions(0, static_cast<Index>(i));
        referenceY_[k] = positions(1, static_cast<Index>(i));
    }
    std::sort(epochKeysSorted_.begin(), epochKeysSorted_.end());
    // Cells of a quarter of the reach, as the disc model's grid.
    epochGrid_.build(epochPositions_, reach_ > 0 ? reach_ / 4 : 1.0);
}

bool KeptNeighbourhoods::reachable(Key a, Key b) const {
    const double dx = referenceX_[a] - referenceX_[b];
    const double dy = referenceY_[a] - referenceY_[b];
    return dx * dx + dy * dy <= reach_ * reach_;
}

void KeptNeighbourhoods::within(Index i, Indices& out, Squares& squared) {
    if (squared.size() != out.size()) throw std::invalid_argument("kept neighbourhoods: squares not as long as out");
    const Key self = keys_[static_cast<std::size_t>(i)];
    if (lists_.size() <= self) lists_.resize(self + 1);
    List& list = lists_[self];
    if (list.epoch != epochs_) {
        list.epoch = epochs_;
        list.newcomers.clear();
        list.newcomersSeen = 0;
        // Its reference: its place at the epoch's start, or where a newcomer was first seen.
        list.epochOthers = epochGrid_.around(referenceX_[self], referenceY_[self], reach_);
    }
    for (; list.newcomersSeen < newcomers_.size(); ++list.newcomersSeen) {
        const Key k = newcomers_[list.newcomersSeen];
        if (k != self && reachable(self, k)) list.newcomers.push_back(k);
    }

    // NeighbourGrid's test, on the current positions.
    const Eigen::Matrix2Xd& positions = *positions_;
    const double x = positions(0, i);
    const double y = positions(1, i);
    const double r2 = radius_ * radius_;
    const auto square = [&](Index j) {
        const double dx = positions(0, j) - x;
        const double dy = positions(1, j) - y;
        return dx * dx + dy * dy;
    };
    const std::size_t start = out.size();
    // Room for every candidate (no zero-fill), cut to the answer at the end.
    out.resize(start + list.epochOthers.size() + list.newcomers.size());
    squared.resize(out.size());
    // Branch-free: every candidate written with its square, the cursor advanced for those kept (a
    // candidate gone or moved has a NaN place, never within).
    Index* w = out.data() + start;
    double* s = squared.data() + start;
    const Candidate* const current = epochCurrent_.data();
    for (const Index e : list.epochOthers) {
        const Candidate& c = current[e];
        const double dx = c.x - x;
        const double dy = c.y - y;
        const double d2 = dx * dx + dy * dy;
        *w = c.j;
        *s = d2;
        const int kept = static_cast<int>(c.j != i) & static_cast<int>(d2 <= r2);
        w += kept;
        s += kept;
    }
    std::size_t end = static_cast<std::size_t>(w - out.data());
    tail_.clear();
    for (const Key k : list.newcomers) {
        const Index j = keyToCurrent_[k];
        if (j < 0 || j == i) continue;
        const double d2 = square(j);
        if (d2 <= r2) tail_.emplace_back(j, d2);
    }
    if (!tail_.empty()) {
        // A vehicle may be a newcomer twice (it moved again): once in the answer.
        std::sort(tail_.begin(), tail_.end());
        tail_.erase(std::unique(tail_.begin(), tail_.end()), tail_.end());
    }
    if (!ascending_ && !std::is_sorted(out.begin() + static_cast<std::ptrdiff_t>(start),
                                       out.begin() + static_cast<std::ptrdiff_t>(end))) {
        // Keys whose order is not the positions' order from step to step: correct, only slower.
        for (std::size_t k = start; k < end; ++k) tail_.emplace_back(out[k], squared[k]);
        std::sort(tail_.begin(), tail_.end());
        end = start;
    }
    // The few newcomers merged in from the back, in place (a list ascends: its epoch's candidates
    // map to ascending current indices while the vehicles keep their order, else sorted above).
    std::size_t to = end + tail_.size();
    const std::size_t size = to;
    for (std::size_t from = end, t = tail_.size(); t > 0;) {
        --to;
        if (from > start && out[from - 1] > tail_[t - 1].first) {
            --from;
            out[to] = out[from];
            squared[to] = squared[from];
        } else {
            --t;
            out[to] = tail_[t].first;
            squared[to] = tail_[t].second;
        }
    }
    out.resize(size);
    squared.resize(size);
}

}  // namespace sbsim::radio
