#include "sbsim/facilities/LocalDynamicMap.h"

#include <algorithm>

namespace sbsim::facilities {

std::size_t LocalDynamicMap::home(StationIndex station) const {
    // Fibonacci hashing: consecutive indices spread over the table.
    return static_cast<std::size_t>((static_cast<std::uint64_t>(station) * 0x9E3779B97F4A7C15ULL) >> 32) &
           (slots_.size() - 1);
}

std::size_t LocalDynamicMap::slotOf(StationIndex station) const {
    const std::size_t mask = slots_.size() - 1;
    const std::uint32_t key = station + 1;
    std::size_t slot = home(station);
    while (slots_[slot].key != 0 && slots_[slot].key != key) slot = (slot + 1) & mask;
    return slot;
}

void LocalDynamicMap::grow() {
    slots_.assign(std::max<std::size_t>(16, slots_.size() * 2), Slot{});
    for (std::size_t k = 0; k < items_.size(); ++k) {
        const StationIndex station = items_[k].second.stationIndex;
        slots_[slotOf(station)] = {station + 1, static_cast<std::uint32_t>(k)};
    }
}

void LocalDynamicMap::update(StationIndex station, const CamContent& cam, kernel::SimTime now) {
    if (cam.generationTime + kLifetime < now) return;
    if (2 * (items_.size() + 1) > slots_.size()) grow();
    const std::size_t slot = slotOf(station);
    if (slots_[slot].key == 0) {
        slots_[slot] = {station + 1, static_cast<std::uint32_t>(items_.size())};
        items_.emplace_back(cam.station, Entry{cam, now, station});
        due_.emplace(items_.back().second.expiry(), station);
        return;
    }
    Entry& entry = items_[slots_[slot].position].second;
    if (entry.cam.generationTime <= cam.generationTime) {
        entry.cam = cam;  // assigned in place: the strings and path history reuse their storage
        entry.receivedAt = now;
    }
}

void LocalDynamicMap::erase(std::size_t slot) {
    const std::size_t mask = slots_.size() - 1;
    const std::size_t position = slots_[slot].position;
    // Backward-shift deletion: a later slot of the probe run moves into the hole unless its home
    // lies cyclically within (hole, its place].
    std::size_t hole = slot;
    for (std::size_t next = (slot + 1) & mask; slots_[next].key != 0; next = (next + 1) & mask) {
        const std::size_t h = home(slots_[next].key - 1);
        const bool stays = hole <= next ? (hole < h && h <= next) : (hole < h || h <= next);
        if (!stays) {
            slots_[hole] = slots_[next];
            hole = next;
        }
    }
    slots_[hole] = Slot{};
    // The last item fills the erased one's place in items_.
    const std::size_t last = items_.size() - 1;
    if (position != last) {
        slots_[slotOf(items_[last].second.stationIndex)].position = static_cast<std::uint32_t>(position);
        items_[position] = std::move(items_[last]);
    }
    items_.pop_back();
}

void LocalDynamicMap::dropExpired(kernel::SimTime now) {
    while (!due_.empty() && due_.top().first < now) {
        Due item = due_.top();
        due_.pop();
        if (slots_.empty()) continue;
        const std::size_t slot = slotOf(item.second);
        if (slots_[slot].key == 0) continue;
        const Entry& entry = items_[slots_[slot].position].second;
        if (entry.expiry() < now) {
            erase(slot);
        } else {
            item.first = entry.expiry();
            due_.push(item);
        }
    }
}

const LocalDynamicMap::Entry* LocalDynamicMap::find(StationIndex station) const {
    if (slots_.empty()) return nullptr;
    const std::size_t slot = slotOf(station);
    return slots_[slot].key == 0 ? nullptr : &items_[slots_[slot].position].second;
}

const LocalDynamicMap::Entry* LocalDynamicMap::find(std::string_view station) const {
    const auto it = std::find_if(items_.begin(), items_.end(), [&](const Item& item) { return item.first == station; });
    return it == items_.end() ? nullptr : &it->second;
}

std::size_t LocalDynamicMap::count(kernel::SimTime now, const std::function<bool(const Entry&)>& predicate) const {
    return static_cast<std::size_t>(std::count_if(items_.begin(), items_.end(), [&](const Item& item) {
        return item.second.expiry() >= now && predicate(item.second);
    }));
}

}  // namespace sbsim::facilities
