#include "sbsim/radio/geonet/DuplicatePacketList.h"

#include <algorithm>

namespace sbsim::radio::geonet {

bool DuplicatePacketList::contains(const PacketId& id) const {
    const auto it = bySource_.find(id.source);
    if (it == bySource_.end()) return false;
    const Recent& r = it->second;
    return std::find(r.sequence.begin(), r.sequence.begin() + static_cast<std::ptrdiff_t>(r.size), id.sequence) !=
           r.sequence.begin() + static_cast<std::ptrdiff_t>(r.size);
}

bool DuplicatePacketList::seen(const PacketId& id) {
    if (contains(id)) return true;
    Recent& r = bySource_[id.source];
    r.sequence[r.next] = id.sequence;
    r.next = (r.next + 1) % kLength;
    r.size = std::min(r.size + 1, kLength);
    return false;
}

}  // namespace sbsim::radio::geonet
