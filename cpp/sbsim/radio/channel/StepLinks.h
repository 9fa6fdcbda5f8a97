#pragma once

#include <cstdint>
#include <vector>

#include "sbsim/kernel/DefaultInitAllocator.h"
#include "sbsim/radio/channel/ChannelStations.h"

namespace sbsim::radio {

/// A sender's links for one SUMO step, shared by every frame it sends in that step and left
/// unchanged while one is on the air: its receivers in the order a frame reaches them, each link's
/// distance bin and distance, its tier — drawn per frame (its Link then in the frame's own vector,
/// in the same order) or interference only — and an interference-only link's fixed power. Frames read the
/// interference-only links here instead of each writing its own copy of them (on a full city four
/// links in five).
struct StepLinks {
    using Slot = ChannelStations::Slot;
    __extension__ typedef unsigned __int128 Units;  // Reception's: 2^-64 mW

    /// The individual links' columns, resized for every candidate and written whole (resizeLinks).
    template <typename T>
    using Column = std::vector<T, kernel::DefaultInitAllocator<T>>;

    Column<Slot> receivers;
    Column<std::uint32_t> bin;  // distance / Medium::kDistanceBin
    Column<double> distance;
    enum Tier : std::uint8_t {
        kBelowFloor = 0,    // interference only, below the floor: no part of what its receiver hears
        kInterference = 1,  // interference only: adds `units` to what its receiver hears
        kDrawn = 2,         // drawn per frame
    };
    Column<std::uint8_t> tier;
    Column<Units> units;  // an interference-only link's power (0 for a drawn one)

    /// The far tier (ChannelSettings::farCellM): whole cells beyond the far range, each one figure
    /// for all its receivers — the mean power at the cell's centre (0: below the floor), its
    /// occupants this step and the centre's distance bin (for the link counts).
    std::vector<std::int32_t> farCell;
    std::vector<Units> farUnits;
    std::vector<std::uint32_t> farOccupants, farBin;

    std::size_t size() const { return receivers.size(); }
    /// The individual links' columns at `n` links (the far cells' untouched): sized for every
    /// candidate, written through pointers, then cut to what was kept.
    void resizeLinks(std::size_t n) {
        receivers.resize(n);
        distance.resize(n);
        bin.resize(n);
        tier.resize(n);
        units.resize(n);
    }
    void clear() {
        receivers.clear();
        bin.clear();
        distance.clear();
        tier.clear();
        units.clear();
        farCell.clear();
        farUnits.clear();
        farOccupants.clear();
        farBin.clear();
    }
};

}  // namespace sbsim::radio
