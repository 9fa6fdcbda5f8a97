#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/CounterRandom.h"

namespace sbsim::radio {

class Receiver;

/// The channel model's stations (equipped vehicles and roadside units), struct-of-arrays by slot;
/// a slot is never reused. Where each was at the last SUMO step and its receiving side then, which
/// the medium refreshes once a step and the link budget reads.
struct ChannelStations {
    using Slot = std::int32_t;

    std::unordered_map<std::string, Slot> slotOf;
    std::vector<std::string> ids;
    std::vector<std::uint64_t> keys;   // CounterRandom::keyOf(id)
    std::vector<std::uint32_t> index;  // the medium's Medium::stationIndex(id)
    std::vector<double> x, y;
    std::vector<std::uint8_t> present;  // in the last snapshot
    std::vector<Receiver*> receiver;    // the receiving side as of the last step; null: gone
    std::optional<kernel::SimTime> refreshedAt;
    std::vector<Slot> slotOfIndex;  // per snapshot index, -1 = not a station

    Slot size() const { return static_cast<Slot>(ids.size()); }
    /// Makes `id`, not a station yet, the next slot (absent, at the origin); `stationIndex` is its
    /// Medium::stationIndex().
    Slot add(const std::string& id, std::uint32_t stationIndex) {
        const Slot s = size();
        slotOf.emplace(id, s);
        ids.push_back(id);
        keys.push_back(CounterRandom::keyOf(id));
        index.push_back(stationIndex);
        x.push_back(0);
        y.push_back(0);
        present.push_back(0);
        receiver.push_back(nullptr);
        return s;
    }
};

}  // namespace sbsim::radio
