#pragma once

#include <climits>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::radio {

/// When each of a set of stations last heard something, by the station's key (CounterRandom::keyOf):
/// an open-addressing table (linear probing, at most half full), asked once per reception, where a
/// node-based map's buckets and nodes cost several cache misses each.
class SBSIM_API LastHeard {
public:
    /// Records that `station` heard at `now`; returns when it heard last before, if ever.
    std::optional<kernel::SimTime> hear(std::uint64_t station, kernel::SimTime now);
    /// Forgets the stations that last heard before `before`.
    void forgetBefore(kernel::SimTime before);
    std::size_t size() const { return used_; }

private:
    static constexpr kernel::SimTime::rep kFree = INT64_MIN;
    struct Entry {
        std::uint64_t key = 0;
        kernel::SimTime::rep heardNs = kFree;
    };
    void rebuild(std::size_t slots);

    std::vector<Entry> table_;
    std::size_t used_ = 0;
};

}  // namespace sbsim::radio
