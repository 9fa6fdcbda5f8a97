#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace sbsim::radio {

/// A loss per unordered pair of station slots, for one SUMO step (LinkBudget: the buildings' loss,
/// the same both ways). Open addressing over flat arrays, entries of earlier steps told apart by a
/// stamp, so starting a step clears nothing: std::unordered_map's node per entry cost about as
/// much as the building walk it saved.
class PairLosses {
public:
    /// Forgets every entry.
    void newStep() {
        if (++step_ == 0) {  // wrapped: every stamp could look current
            std::fill(stamp_.begin(), stamp_.end(), 0);
            step_ = 1;
        }
        size_ = 0;
    }

    /// The loss of the pair (a, b) this step, if stored.
    const double* find(int a, int b) const {
        if (stamp_.empty()) return nullptr;
        const std::uint64_t k = key(a, b);
        for (std::size_t i = slot(k);; i = (i + 1) & mask_) {
            if (stamp_[i] != step_) return nullptr;
            if (keys_[i] == k) return &values_[i];
        }
    }

    /// Stores the pair's loss (not already stored this step).
    void add(int a, int b, double loss) {
        if (2 * (size_ + 1) > stamp_.size()) grow();
        place(key(a, b), loss);
        ++size_;
    }

private:
    static std::uint64_t key(int a, int b) {
        const auto [lo, hi] = std::minmax(a, b);
        return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(lo)) << 32) | static_cast<std::uint32_t>(hi);
    }
    std::size_t slot(std::uint64_t k) const {
        return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> 32) & mask_;  // Fibonacci hashing
    }
    void place(std::uint64_t k, double loss) {
        std::size_t i = slot(k);
        while (stamp_[i] == step_) i = (i + 1) & mask_;
        stamp_[i] = step_;
        keys_[i] = k;
        values_[i] = loss;
    }
    void grow() {
        std::vector<std::uint32_t> stamp(std::max<std::size_t>(1024, 2 * stamp_.size()), 0);
        std::vector<std::uint64_t> keys(stamp.size());
        std::vector<double> values(stamp.size());
        std::swap(stamp, stamp_);
        std::swap(keys, keys_);
        std::swap(values, values_);
        mask_ = stamp_.size() - 1;
        const std::uint32_t current = step_;
        for (std::size_t i = 0; i < stamp.size(); ++i) {
            if (stamp[i] == current) place(keys[i], values[i]);
        }
    }

    std::vector<std::uint32_t> stamp_;  // the step an entry belongs to
    std::vector<std::uint64_t> keys_;   // lesser slot << 32 | greater slot
    std::vector<double> values_;
    std::size_t mask_ = 0, size_ = 0;
    std::uint32_t step_ = 1;
};

}  // namespace sbsim::radio
