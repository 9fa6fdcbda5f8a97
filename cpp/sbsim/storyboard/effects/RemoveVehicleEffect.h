#pragma once

#include <string>

#include "sbsim/storyboard/WorldEffect.h"

namespace sbsim::storyboard {

/// Once, at activation: the vehicle leaves the simulation (OpenSCENARIO's DeleteEntityAction),
/// whether it runs or waits to depart; one that left already is not looked for. Its stories end
/// with reason "vehicle_left" at the next step. Deactivation does nothing.
class RemoveVehicleEffect : public WorldEffect {
public:
    /// Throws std::invalid_argument for an empty id.
    explicit RemoveVehicleEffect(std::string id);
    void apply(WorldScope& scope) override { scope.stack().removeVehicle(id_); }
    void remove(WorldScope& /*scope*/) override {}
    std::string describe() const override;
    const std::string& id() const { return id_; }

private:
    std::string id_;
};

}  // namespace sbsim::storyboard
