#pragma once

#include "sbsim/kernel/SimTime.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::storyboard {

/// Identifies the snapshot a condition's per-step cache was computed for, so test() can recompute
/// the cache itself if prepare() was not called for this step.
struct SnapshotStamp {
    const traffic::VehicleSnapshot* snapshot = nullptr;
    kernel::SimTime time;
    traffic::VehicleSnapshot::Index size = -1;

    static SnapshotStamp of(const traffic::VehicleSnapshot& s) { return {&s, s.time(), s.size()}; }
    bool operator==(const SnapshotStamp&) const = default;
};

}  // namespace sbsim::storyboard
