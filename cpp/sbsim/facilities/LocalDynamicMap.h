#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <queue>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sbsim/facilities/Cam.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::facilities {

/// One station's local dynamic map: the stations it knows from their CAMs, each with its last
/// CAM's content. An entry lives kLifetime past that CAM's generation time (Artery's 1.1 s: one
/// T_GenCamMax plus margin, so a station sending at 1 Hz never drops out between two CAMs).
class SBSIM_API LocalDynamicMap {
public:
    static constexpr kernel::SimTime kLifetime = kernel::SimTime::fromMilliseconds(1100);

    struct Entry {
        CamContent cam;
        kernel::SimTime receivedAt;
        kernel::SimTime expiry() const { return cam.generationTime + kLifetime; }
        /// Time since the CAM was generated.
        kernel::SimTime age(kernel::SimTime now) const { return now - cam.generationTime; }
    };

    /// Takes in a CAM received at `now`: replaces the sender's entry. A CAM already past its
    /// lifetime is ignored.
    void update(const CamContent& cam, kernel::SimTime now);
    /// Drops the entries whose lifetime ended before `now`.
    void dropExpired(kernel::SimTime now);

    /// The entry of `station`, or null.
    const Entry* find(std::string_view station) const;
    /// Entries in ascending station order (those past their lifetime may linger until dropExpired).
    const std::map<std::string, Entry, std::less<>>& entries() const { return entries_; }
    std::size_t size() const { return entries_.size(); }
    /// How many entries, alive at `now`, satisfy `predicate`.
    std::size_t count(kernel::SimTime now, const std::function<bool(const Entry&)>& predicate) const;

private:
    std::map<std::string, Entry, std::less<>> entries_;
    // One item per entry, keyed by an expiry at or before the entry's (a CAM only moves its
    // sender's expiry later): dropExpired() pops what is due and erases the entry, or queues it
    // again at its later expiry. So each entry is visited about once per lifetime, not the whole
    // map on every trigger (with hundreds of neighbours some entry is always about to expire).
    using Due = std::pair<kernel::SimTime, std::string>;
    std::priority_queue<Due, std::vector<Due>, std::greater<>> due_;
};

}  // namespace sbsim::facilities
