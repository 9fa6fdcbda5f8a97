#include "sbsim/traffic/EquippedVehicles.h"

#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::traffic {

EquippedVehicles::EquippedVehicles(kernel::Module& sumo, Penetration penetration) : penetration_(penetration) {
    sumo.subscribe(SumoBridge::departedSignal, *this);
}

std::optional<bool> EquippedVehicles::isEquipped(std::string_view id) const {
    const auto it = seen_.find(std::string(id));
    if (it == seen_.end()) return std::nullopt;
    return it->second;
}

void EquippedVehicles::receiveSignal(kernel::Module& source, kernel::SignalId id, std::string_view value) {
    if (id != SumoBridge::departedSignal) return;
    // A vehicle id SUMO gives again (added anew after it arrived) became equipped once, at first.
    const auto [it, first] = seen_.emplace(std::string(value), penetration_.equipped(value));
    if (!first || !it->second) return;
    equipped_.push_back({it->first, source.simTime()});
    if (observer_) observer_(source.simTime(), it->first);
}

}  // namespace sbsim::traffic
