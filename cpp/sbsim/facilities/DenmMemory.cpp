#include "sbsim/facilities/DenmMemory.h"

#include <algorithm>

namespace sbsim::facilities {

std::optional<DenmPhase> DenmMemory::received(const DenmContent& denm, kernel::SimTime now) {
    auto it = entries_.find(denm.action);
    if (denm.termination) {
        if (it == entries_.end() || denm.referenceTime < it->second.denm.referenceTime) return std::nullopt;
        entries_.erase(it);
        return DenmPhase::Terminate;
    }
    if (denm.expiry() < now) return std::nullopt;
    if (it == entries_.end()) {
        earliest_ = std::min(earliest_, denm.expiry());
        entries_.emplace(denm.action, Entry{denm, now, now, now});
        return DenmPhase::New;
    }
    if (!(denm.referenceTime < it->second.denm.referenceTime)) it->second.lastHeardAt = now;
    if (!(it->second.denm.referenceTime < denm.referenceTime)) return std::nullopt;
    earliest_ = std::min(earliest_, denm.expiry());  // a new version may end sooner
    it->second.denm = denm;
    it->second.receivedAt = now;
    return DenmPhase::Update;
}

std::vector<DenmMemory::Entry> DenmMemory::dropExpired(kernel::SimTime now) {
    std::vector<Entry> dropped;
    if (!(earliest_ < now)) return dropped;  // none due: no walk
    earliest_ = kernel::SimTime::max();
    for (auto it = entries_.begin(); it != entries_.end();) {
        if (it->second.denm.expiry() < now) {
            dropped.push_back(std::move(it->second));
            it = entries_.erase(it);
        } else {
            earliest_ = std::min(earliest_, it->second.denm.expiry());
            ++it;
        }
    }
    return dropped;
}

const DenmMemory::Entry* DenmMemory::find(const ActionId& action) const {
    const auto it = entries_.find(action);
    return it == entries_.end() ? nullptr : &it->second;
}

std::size_t DenmMemory::count(int cause, kernel::SimTime now) const {
    return static_cast<std::size_t>(std::count_if(entries_.begin(), entries_.end(), [&](const auto& kv) {
        return kv.second.denm.cause == cause && kv.second.denm.expiry() >= now;
    }));
}

}  // namespace sbsim::facilities
