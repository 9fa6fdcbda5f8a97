#include "sbsim/facilities/StationRegistry.h"

#include <atomic>

namespace sbsim::facilities {

std::uint64_t StationRegistry::nextIdentity() {
    static std::atomic<std::uint64_t> next{1};
    return next++;
}

StationFacilities& StationRegistry::of(Index station) {
    if (station >= byIndex_.size()) byIndex_.resize(station + 1);
    auto& slot = byIndex_[station];
    if (!slot) {
        slot = std::make_unique<StationFacilities>();
        ++size_;
    }
    return *slot;
}

const StationFacilities* StationRegistry::find(std::string_view station) const {
    const auto index = ids_.find(station);
    return index ? find(*index) : nullptr;
}

void StationRegistry::remove(std::string_view station) {
    const auto index = ids_.find(station);
    if (!index || *index >= byIndex_.size() || !byIndex_[*index]) return;
    byIndex_[*index].reset();
    --size_;
}

void StationRegistry::dropExpired(Index station, kernel::SimTime now) {
    if (station >= byIndex_.size() || !byIndex_[station]) return;
    for (const DenmMemory::Entry& e : byIndex_[station]->dropExpired(now)) {
        report({now, DenmPhase::Expired, name(station), e.denm.action, e.denm.cause});
    }
}

void StationRegistry::dropExpired(std::string_view station, kernel::SimTime now) {
    if (const auto index = ids_.find(station)) dropExpired(*index, now);
}

void StationRegistry::report(const DenmPhaseEvent& event) const {
    if (sink_ != nullptr) sink_->denmPhase(event);
}

}  // namespace sbsim::facilities
