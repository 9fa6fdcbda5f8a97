#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <queue>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sbsim/facilities/Cam.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/StationIds.h"

namespace sbsim::facilities {

/// One station's local dynamic map: the stations it knows from their CAMs, each with its last
/// CAM's content. An entry lives kLifetime past that CAM's generation time (Artery's 1.1 s: one
/// T_GenCamMax plus margin, so a station sending at 1 Hz never drops out between two CAMs).
///
/// Keyed by the sending station's index (radio::StationIds, the registry's): a CAM is taken in
/// with one probe of a small open-addressing table instead of a walk down a string-keyed tree
/// (which, with a few hundred neighbours, was half of a CA run's time).
class SBSIM_API LocalDynamicMap {
public:
    static constexpr kernel::SimTime kLifetime = kernel::SimTime::fromMilliseconds(1100);
    using StationIndex = radio::StationIds::Index;

    struct Entry {
        CamContent cam;
        kernel::SimTime receivedAt;
        StationIndex stationIndex = 0;  ///< of cam.station
        kernel::SimTime expiry() const { return cam.generationTime + kLifetime; }
        /// Time since the CAM was generated.
        kernel::SimTime age(kernel::SimTime now) const { return now - cam.generationTime; }
    };
    /// (station id, entry), as a map's element, so `for (const auto& [id, entry] : entries())` reads.
    using Item = std::pair<std::string, Entry>;

    /// Takes in a CAM of station `station` (the index of cam.station) received at `now`: replaces
    /// the station's entry unless it holds a newer CAM. A CAM already past its lifetime is ignored.
    void update(StationIndex station, const CamContent& cam, kernel::SimTime now);
    /// Drops the entries whose lifetime ended before `now`.
    void dropExpired(kernel::SimTime now);

    /// The entry of `station`, or null.
    const Entry* find(StationIndex station) const;
    /// The entry of the station called `station`, or null (a linear search: for tests and tools).
    const Entry* find(std::string_view station) const;
    /// The entries in no particular order (drops move entries): whoever needs an order sorts, by
    /// id or by snapshot index. Those past their lifetime may linger until dropExpired.
    const std::vector<Item>& entries() const { return items_; }
    std::size_t size() const { return items_.size(); }
    /// How many entries, alive at `now`, satisfy `predicate`.
    std::size_t count(kernel::SimTime now, const std::function<bool(const Entry&)>& predicate) const;

private:
    /// The slot of `station` in slots_: the one holding it, or the empty one where it would go.
    std::size_t slotOf(StationIndex station) const;
    std::size_t home(StationIndex station) const;
    void grow();
    void erase(std::size_t slot);

    std::vector<Item> items_;
    // Open addressing with linear probing over items_, at most half full. The slot holds the
    // station too, so a probe past other stations reads no item (each a cache miss away).
    struct Slot {
        std::uint32_t key = 0;       // station + 1; 0: empty
        std::uint32_t position = 0;  // in items_
    };
    std::vector<Slot> slots_;
    // One item per entry, keyed by an expiry at or before the entry's (a CAM only moves its
    // sender's expiry later): dropExpired() pops what is due and erases the entry, or queues it
    // again at its later expiry. So each entry is visited about once per lifetime, not the whole
    // map on every trigger (with hundreds of neighbours some entry is always about to expire).
    using Due = std::pair<kernel::SimTime, StationIndex>;
    std::priority_queue<Due, std::vector<Due>, std::greater<>> due_;
};

}  // namespace sbsim::facilities
