#include "sbsim/facilities/LocalDynamicMap.h"

#include <algorithm>

namespace sbsim::facilities {

void LocalDynamicMap::update(const CamContent& cam, kernel::SimTime now) {
    if (cam.generationTime + kLifetime < now) return;
    auto it = entries_.find(cam.station);
    if (it == entries_.end()) {
        it = entries_.emplace(cam.station, Entry{cam, now}).first;
    } else if (it->second.cam.generationTime <= cam.generationTime) {
        it->second.cam = cam;  // assigned in place: the strings and path history reuse their storage
        it->second.receivedAt = now;
    } else {
        return;
    }
    earliestExpiry_ = std::min(earliestExpiry_, it->second.expiry());
}

void LocalDynamicMap::dropExpired(kernel::SimTime now) {
    if (!(earliestExpiry_ < now)) return;
    earliestExpiry_ = kernel::SimTime::max();
    for (auto it = entries_.begin(); it != entries_.end();) {
        if (it->second.expiry() < now) {
            it = entries_.erase(it);
        } else {
            earliestExpiry_ = std::min(earliestExpiry_, it->second.expiry());
            ++it;
        }
    }
}

const LocalDynamicMap::Entry* LocalDynamicMap::find(std::string_view station) const {
    const auto it = entries_.find(station);
    return it == entries_.end() ? nullptr : &it->second;
}

std::size_t LocalDynamicMap::count(kernel::SimTime now, const std::function<bool(const Entry&)>& predicate) const {
    return static_cast<std::size_t>(std::count_if(entries_.begin(), entries_.end(), [&](const auto& kv) {
        return kv.second.expiry() >= now && predicate(kv.second);
    }));
}

}  // namespace sbsim::facilities
