#include "sbsim/facilities/StationRegistry.h"

namespace sbsim::facilities {

StationFacilities& StationRegistry::of(const std::string& station) {
    auto it = stations_.find(station);
    if (it == stations_.end()) it = stations_.emplace(station, std::make_unique<StationFacilities>()).first;
    return *it->second;
}

const StationFacilities* StationRegistry::find(std::string_view station) const {
    const auto it = stations_.find(station);
    return it == stations_.end() ? nullptr : it->second.get();
}

void StationRegistry::remove(std::string_view station) {
    const auto it = stations_.find(station);
    if (it != stations_.end()) stations_.erase(it);
}

void StationRegistry::dropExpired(const std::string& station, kernel::SimTime now) {
    const auto it = stations_.find(station);
    if (it == stations_.end()) return;
    for (const DenmMemory::Entry& e : it->second->dropExpired(now)) {
        report({now, DenmPhase::Expired, station, e.denm.action, e.denm.cause});
    }
}

void StationRegistry::report(const DenmPhaseEvent& event) const {
    if (sink_ != nullptr) sink_->denmPhase(event);
}

}  // namespace sbsim::facilities
