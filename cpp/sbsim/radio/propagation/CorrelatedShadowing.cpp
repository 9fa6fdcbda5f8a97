#include "sbsim/radio/propagation/CorrelatedShadowing.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "sbsim/radio/CounterRandom.h"

namespace sbsim::radio {

namespace {
std::size_t hashOf(std::uint64_t lo, std::uint64_t hi) {
    return static_cast<std::size_t>(CounterRandom::mix(lo ^ CounterRandom::mix(hi)));
}
}  // namespace

CorrelatedShadowing::CorrelatedShadowing(double sigmaDb, double correlationDistance, std::uint64_t seed)
    : sigmaDb_(sigmaDb), correlationDistance_(correlationDistance), seed_(seed) {
    if (!(sigmaDb >= 0)) throw std::invalid_argument("shadowing sigma must be >= 0 dB");
    if (!(correlationDistance > 0)) throw std::invalid_argument("shadowing correlation distance must be > 0 m");
}

std::size_t CorrelatedShadowing::slotOf(const Key& key) const { return hashOf(key.lo, key.hi) & (table_.size() - 1); }

CorrelatedShadowing::Index CorrelatedShadowing::pair(std::uint64_t a, std::uint64_t b, kernel::SimTime now) {
    const Key key{std::min(a, b), std::max(a, b)};
    if (2 * (used_ + 1) > table_.size()) rebuild(std::max<std::size_t>(1024, 2 * table_.size()));
    const std::size_t mask = table_.size() - 1;
    std::size_t at = slotOf(key);
    while (table_[at].index != kEmpty && !(table_[at].key == key)) at = (at + 1) & mask;
    Slot& slot = table_[at];
    if (slot.index == kEmpty) {
        if (free_.empty()) {
            slot.index = static_cast<Index>(states_.size());
            states_.emplace_back();
        } else {
            slot.index = free_.back();
            free_.pop_back();
            states_[slot.index] = State{};
        }
        slot.key = key;
        ++used_;
    }
    states_[slot.index].seen = now;
    return slot.index;
}

void CorrelatedShadowing::pairs(std::uint64_t a, const std::vector<std::uint64_t>& others, kernel::SimTime now,
                                std::vector<Index>& out) {
    const std::size_t n = others.size();
    out.resize(n);
    // Room for every one first, so the slots fetched ahead stay where they are.
    std::size_t slots = std::max<std::size_t>(1024, table_.size());
    while (2 * (used_ + n) > slots) slots *= 2;
    if (slots != table_.size()) rebuild(slots);
    constexpr std::size_t kAhead = 8;
    const auto fetch = [&](std::size_t k) {
        __builtin_prefetch(&table_[slotOf({std::min(a, others[k]), std::max(a, others[k])})], 1);
    };
    for (std::size_t k = 0; k < std::min(n, kAhead); ++k) fetch(k);
    for (std::size_t k = 0; k < n; ++k) {
        if (k + kAhead < n) fetch(k + kAhead);
        out[k] = pair(a, others[k], now);
    }
}

void CorrelatedShadowing::rebuild(std::size_t slots) {
    Table<Slot> old(slots);
    old.swap(table_);
    const std::size_t mask = slots - 1;
    for (const Slot& s : old) {
        if (s.index == kEmpty) continue;
        std::size_t at = slotOf(s.key);
        while (table_[at].index != kEmpty) at = (at + 1) & mask;
        table_[at] = s;
    }
}

double CorrelatedShadowing::valueDb(Index pair, std::uint64_t a, double ax, double ay, std::uint64_t b, double bx,
                                    double by) {
    State& s = states_[pair];
    if (a > b) {  // the pair's own order: its first station has the smaller key
        std::swap(a, b);
        std::swap(ax, bx);
        std::swap(ay, by);
    }
    // The pair's n-th value draws from (seed, pair, n) and nothing else.
    const auto draw = [&] { return CounterRandom(seed_, a, s.draws++, b, DrawPurpose::CorrelatedShadowing).normal(); };
    if (s.fresh) {
        s.z = draw();
        s.fresh = false;
    } else {
        const double dax = ax - s.loX, day = ay - s.loY, dbx = bx - s.hiX, dby = by - s.hiY;
        const double moved = std::sqrt(dax * dax + day * day) + std::sqrt(dbx * dbx + dby * dby);
        if (moved > 0) {
            const double rho = std::exp(-moved / correlationDistance_);
            s.z = rho * s.z + std::sqrt(1 - rho * rho) * draw();
        }
    }
    s.loX = ax;
    s.loY = ay;
    s.hiX = bx;
    s.hiY = by;
    return sigmaDb_ * s.z;
}

void CorrelatedShadowing::forget(kernel::SimTime now) {
    if (now - lastSweep_ < kForgetAfter) return;
    lastSweep_ = now;
    std::size_t forgotten = 0;
    for (Slot& slot : table_) {
        if (slot.index != kEmpty && now - states_[slot.index].seen > kForgetAfter) {
            free_.push_back(slot.index);
            slot.index = kEmpty;
            ++forgotten;
        }
    }
    if (forgotten == 0) return;
    ++generation_;
    used_ -= forgotten;
    // Linear probing cannot just empty slots (a probe would stop early): the table is laid out
    // afresh, at most half full.
    std::size_t slots = 1024;
    while (slots < 2 * used_) slots *= 2;
    rebuild(slots);
}

}  // namespace sbsim::radio
