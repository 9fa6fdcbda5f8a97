#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Module.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/traffic/Penetration.h"

namespace sbsim::traffic {

/// Which of the run's vehicles carry V2X equipment and since when: each departing vehicle is
/// equipped or not by the run's Penetration (the same draw that gives it services), and becomes
/// so when it departs. The summary names them, the event log gets a line each, the statistics
/// file marks their rows.
class SBSIM_API EquippedVehicles : private kernel::Listener {
public:
    /// A vehicle that became equipped, and when (its first departure).
    struct Entry {
        std::string vehicle;
        kernel::SimTime since;
    };
    /// Told of each vehicle as it becomes equipped.
    using Observer = std::function<void(kernel::SimTime, const std::string&)>;

    /// `sumo` emits traffic::SumoBridge's departed signal (the bridge, or a stand-in).
    EquippedVehicles(kernel::Module& sumo, Penetration penetration);
    EquippedVehicles(const EquippedVehicles&) = delete;
    EquippedVehicles& operator=(const EquippedVehicles&) = delete;

    void onEquipped(Observer observer) { observer_ = std::move(observer); }
    const Penetration& penetration() const { return penetration_; }
    /// The equipped vehicles in the order they became so.
    const std::vector<Entry>& equipped() const { return equipped_; }
    /// Vehicles that departed so far, equipped or not.
    std::size_t seen() const { return seen_.size(); }
    /// Whether `id` is equipped; none for an id no vehicle of this run had (a roadside unit, "").
    std::optional<bool> isEquipped(std::string_view id) const;

private:
    void receiveSignal(kernel::Module& source, kernel::SignalId id, std::string_view value) override;

    Penetration penetration_;
    Observer observer_;
    std::vector<Entry> equipped_;
    std::unordered_map<std::string, bool> seen_;  // each departed vehicle: equipped?
};

}  // namespace sbsim::traffic
