#include "sbsim/traffic/VehicleRegistry.h"

#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::traffic {

VehicleRegistry::VehicleRegistry()
    : makeController_([](const std::string& id) { return std::make_unique<VehicleController>(id); }) {}

void VehicleRegistry::attach(SumoBridge& sumo) {
    MaxSpeedListener* listener = &sumo.maxSpeedListener();
    makeController_ = [listener](const std::string& id) { return std::make_unique<VehicleController>(id, listener); };
    // Counted and shown with SUMO's own warnings (and in --sumo-log).
    warn_ = [&sumo](const std::string& message) { sumo.warnings().take("Warning: " + message + "\n"); };
}

std::shared_ptr<VehicleRegistry::Vehicle> VehicleRegistry::of(const std::string& id) {
    auto& entry = vehicles_[id];
    if (!entry) entry = std::make_shared<Vehicle>(makeController_(id), warn_);
    return entry;
}

}  // namespace sbsim::traffic
