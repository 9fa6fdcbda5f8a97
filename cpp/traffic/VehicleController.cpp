#include "sbsim/traffic/VehicleController.h"

#include "sbsim/traffic/SnapshotBuilder.h"

#include <libsumo/Vehicle.h>

namespace sbsim::traffic {

using libsumo::Vehicle;

std::string VehicleController::typeId() const { return Vehicle::getTypeID(id_); }
std::string VehicleController::roadId() const { return Vehicle::getRoadID(id_); }
std::string VehicleController::laneId() const { return Vehicle::getLaneID(id_); }
int VehicleController::laneIndex() const { return Vehicle::getLaneIndex(id_); }
double VehicleController::speed() const { return Vehicle::getSpeed(id_); }
double VehicleController::maxSpeed() const { return Vehicle::getMaxSpeed(id_); }
double VehicleController::emergencyDecel() const { return Vehicle::getEmergencyDecel(id_); }
int VehicleController::speedMode() const { return Vehicle::getSpeedMode(id_); }

void VehicleController::setMaxSpeed(double mps) {
    Vehicle::setMaxSpeed(id_, mps);
    SnapshotBuilder::maxSpeedChanged(id_);  // the snapshot reads max speed only when it changes
}
void VehicleController::setSpeed(double mps) { Vehicle::setSpeed(id_, mps); }
void VehicleController::slowDown(double mps, double seconds) { Vehicle::slowDown(id_, mps, seconds); }
void VehicleController::setSpeedMode(int mode) { Vehicle::setSpeedMode(id_, mode); }
void VehicleController::changeLane(int laneIndex, double seconds) { Vehicle::changeLane(id_, laneIndex, seconds); }
void VehicleController::changeLaneRelative(int offset, double seconds) {
    Vehicle::changeLaneRelative(id_, offset, seconds);
}

}  // namespace sbsim::traffic
