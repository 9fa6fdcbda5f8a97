#include "sbsim/services/ServiceVehicle.h"

namespace sbsim::services {

ServiceVehicle::ServiceVehicle(std::shared_ptr<traffic::VehicleRegistry::Vehicle> vehicle,
                               traffic::VehicleRegistry& registry)
    : VehicleController(vehicle->controller->id()), vehicle_(std::move(vehicle)), registry_(registry) {}

void ServiceVehicle::setMaxSpeed(double mps) {
    // Pushed before the old cap goes: replacing never lets the vehicle's own max speed through.
    const auto old = cap_;
    cap_ = registry_.newToken();
    vehicle_->stack.pushSpeedCap(*cap_, mps);
    if (old) vehicle_->stack.remove(*old);
}

void ServiceVehicle::endMaxSpeed() {
    if (!cap_) return;
    vehicle_->stack.remove(*cap_);
    cap_.reset();
}

}  // namespace sbsim::services
