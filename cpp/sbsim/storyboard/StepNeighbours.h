#pragma once

#include <atomic>
#include <mutex>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/NeighbourGrid.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::storyboard {

/// The storyboard's neighbour grid over one step's snapshot, built when a condition first asks
/// for it (EvaluationContext::neighbours()) rather than every step: the conditions that search
/// neighbours (TTC, speed difference) answer from their own pair sweeps once they run ahead, so
/// in most steps nobody asks. Thread-safe: test() runs on the pool, and the first caller builds
/// while the others wait.
class SBSIM_API StepNeighbours {
public:
    /// The next step: `snapshot` (kept by reference) with cells of `cellSize` m; nothing is built yet.
    void reset(const traffic::VehicleSnapshot& snapshot, double cellSize) {
        snapshot_ = &snapshot;
        cellSize_ = cellSize;
        built_.store(false, std::memory_order_release);
    }

    /// The grid over the snapshot of the last reset(), built on the first call after it.
    const traffic::NeighbourGrid& get() const {
        if (!built_.load(std::memory_order_acquire)) {
            const std::lock_guard lock(mutex_);
            if (!built_.load(std::memory_order_relaxed)) {
                grid_.build(*snapshot_, cellSize_);
                ++builds_;
                built_.store(true, std::memory_order_release);
            }
        }
        return grid_;
    }

    /// Whether the grid of this step was built (some condition asked for it).
    bool built() const { return built_.load(std::memory_order_acquire); }
    /// Grids built since construction: what the laziness saved is steps less this.
    std::size_t builds() const { return builds_; }

private:
    const traffic::VehicleSnapshot* snapshot_ = nullptr;
    double cellSize_ = 1;
    mutable std::mutex mutex_;
    mutable std::atomic<bool> built_{false};
    mutable traffic::NeighbourGrid grid_;
    mutable std::size_t builds_ = 0;
};

}  // namespace sbsim::storyboard
