#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::radio {

/// When each of a set of stations last heard something, by the station's index (StationIds):
/// two arrays sorted by index (indices, times), 12 bytes a station. A frame's receivers, which the
/// media find in an order close to their indices', are matched by one forward walk (hearAll), so
/// the tables of a full city (5,000 senders, ~1,000 stations each) are read sequentially where a
/// hash table's random probes cost a cache miss per reception (a third of the disc model's run).
class SBSIM_API LastHeard {
public:
    using Index = std::uint32_t;

    /// Records that `station` heard at `now`; returns when it heard last before, if ever.
    std::optional<kernel::SimTime> hear(Index station, kernel::SimTime now);
    /// Records that each of `stations` (distinct) heard at `now`, walking them in their order
    /// (fastest when ascending; any order is correct), and appends to `unknown` those that had
    /// not heard since `since` (or never).
    void hearAll(std::span<const Index> stations, kernel::SimTime now, kernel::SimTime since,
                 std::vector<Index>& unknown);
    /// Forgets the stations that last heard before `before`.
    void forgetBefore(kernel::SimTime before);
    std::size_t size() const { return stations_.size(); }

private:
    /// The first position at or after `from` whose station is not below `station`.
    std::size_t seek(std::size_t from, Index station) const;
    /// Merges `newcomers_` (heard at `now`, none known) into the sorted arrays.
    void addNewcomers(kernel::SimTime now);

    std::vector<Index> stations_;                // ascending
    std::vector<kernel::SimTime::rep> heardNs_;  // as stations_
    std::vector<Index> newcomers_;               // scratch of hearAll
};

}  // namespace sbsim::radio
