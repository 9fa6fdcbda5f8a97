#include "sbsim/facilities/LocalDynamicMap.h"

#include <algorithm>

namespace sbsim::facilities {

void LocalDynamicMap::update(const CamContent& cam, kernel::SimTime now) {
    if (cam.generationTime + kLifetime < now) return;
    const auto it = entries_.find(cam.station);
    if (it == entries_.end()) {
        const auto added = entries_.emplace(cam.station, Entry{cam, now}).first;
        due_.emplace(added->second.expiry(), cam.station);
    } else if (it->second.cam.generationTime <= cam.generationTime) {
        it->second.cam = cam;  // assigned in place: the strings and path history reuse their storage
        it->second.receivedAt = now;
    }
}

void LocalDynamicMap::dropExpired(kernel::SimTime now) {
    while (!due_.empty() && due_.top().first < now) {
        Due item = due_.top();
        due_.pop();
        const auto it = entries_.find(item.second);
        if (it == entries_.end()) continue;
        if (it->second.expiry() < now) {
            entries_.erase(it);
        } else {
            item.first = it->second.expiry();
            due_.push(std::move(item));
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
