#include "sbsim/traffic/VehicleController.h"

#include <libsumo/Edge.h>
#include <libsumo/Lane.h>
#include <libsumo/Simulation.h>
#include <libsumo/TraCIDefs.h>
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
double VehicleController::speedFactor() const { return Vehicle::getSpeedFactor(id_); }
Color VehicleController::color() const {
    const libsumo::TraCIColor c = Vehicle::getColor(id_);
    return {static_cast<std::uint8_t>(c.r), static_cast<std::uint8_t>(c.g), static_cast<std::uint8_t>(c.b),
            static_cast<std::uint8_t>(c.a)};
}

void VehicleController::setMaxSpeed(double mps) {
    Vehicle::setMaxSpeed(id_, mps);
    if (listener_ != nullptr) listener_->maxSpeedChanged(id_);  // the snapshot reads max speed only then
}
void VehicleController::setSpeed(double mps) { Vehicle::setSpeed(id_, mps); }
void VehicleController::slowDown(double mps, double seconds) { Vehicle::slowDown(id_, mps, seconds); }
void VehicleController::setSpeedMode(int mode) { Vehicle::setSpeedMode(id_, mode); }
void VehicleController::changeLane(int laneIndex, double seconds) { Vehicle::changeLane(id_, laneIndex, seconds); }
void VehicleController::changeLaneRelative(int offset, double seconds) {
    Vehicle::changeLaneRelative(id_, offset, seconds);
}
void VehicleController::setSpeedFactor(double factor) { Vehicle::setSpeedFactor(id_, factor); }
void VehicleController::setType(const std::string& typeId) {
    Vehicle::setType(id_, typeId);
    if (listener_ != nullptr) listener_->maxSpeedChanged(id_);  // the new type brings its own max speed
}
void VehicleController::setColor(const Color& color) {
    Vehicle::setColor(id_, libsumo::TraCIColor(color.r, color.g, color.b, color.a));
}
int VehicleController::laneCount() const { return libsumo::Edge::getLaneNumber(Vehicle::getRoadID(id_)); }
Position VehicleController::position() const {
    const libsumo::TraCIPosition p = Vehicle::getPosition(id_);
    return {p.x, p.y};
}

namespace {
// SUMO answers "not reachable" with INVALID_DOUBLE_VALUE (a huge negative number).
std::optional<double> reachable(double distance) {
    if (distance < 0 || distance == libsumo::INVALID_DOUBLE_VALUE) return std::nullopt;
    return distance;
}
}  // namespace

std::optional<double> VehicleController::drivingDistance(const std::string& edge, double position) const {
    return reachable(Vehicle::getDrivingDistance(id_, edge, position, 0));
}

std::optional<double> VehicleController::drivingDistanceTo(double x, double y) const {
    return reachable(Vehicle::getDrivingDistance2D(id_, x, y));
}

std::vector<std::string> VehicleController::route() const { return Vehicle::getRoute(id_); }
std::vector<std::string> VehicleController::via() const { return Vehicle::getVia(id_); }
void VehicleController::setVia(const std::vector<std::string>& edges) {
    try {
        Vehicle::setVia(id_, edges);
    } catch (const libsumo::TraCIException& e) {
        throw CommandRefused(e.what());
    }
}
void VehicleController::changeTarget(const std::string& edge) {
    try {
        Vehicle::changeTarget(id_, edge);
    } catch (const libsumo::TraCIException& e) {
        throw CommandRefused(e.what());
    }
}

double VehicleController::stepLength() const { return libsumo::Simulation::getDeltaT(); }
double VehicleController::odometer() const { return Vehicle::getDistance(id_); }
double VehicleController::lateralLanePosition() const { return Vehicle::getLateralLanePosition(id_); }
std::vector<double> VehicleController::laneWidths() const {
    const std::string road = Vehicle::getRoadID(id_);
    const int lanes = libsumo::Edge::getLaneNumber(road);
    std::vector<double> widths;
    widths.reserve(static_cast<std::size_t>(lanes));
    for (int i = 0; i < lanes; ++i) widths.push_back(libsumo::Lane::getWidth(road + "_" + std::to_string(i)));
    return widths;
}
bool VehicleController::sublaneModel() const {
    return std::stod(libsumo::Simulation::getOption("lateral-resolution")) > 0;
}
void VehicleController::changeSublane(double latDist) { Vehicle::changeSublane(id_, latDist); }
int VehicleController::laneChangeMode() const { return Vehicle::getLaneChangeMode(id_); }
void VehicleController::setLaneChangeMode(int mode) { Vehicle::setLaneChangeMode(id_, mode); }
double VehicleController::maxSpeedLat() const { return Vehicle::getMaxSpeedLat(id_); }
void VehicleController::setMaxSpeedLat(double mps) { Vehicle::setMaxSpeedLat(id_, mps); }
std::string VehicleController::parameter(const std::string& key) const { return Vehicle::getParameter(id_, key); }
void VehicleController::setParameter(const std::string& key, const std::string& value) {
    Vehicle::setParameter(id_, key, value);
}
double VehicleController::lanePosition() const { return Vehicle::getLanePosition(id_); }
void VehicleController::moveTo(const std::string& laneId, double position) {
    try {
        Vehicle::moveTo(id_, laneId, position, libsumo::MOVE_TELEPORT);
    } catch (const libsumo::TraCIException& e) {
        throw CommandRefused(e.what());
    }
}
void VehicleController::setRoute(const std::vector<std::string>& edges) {
    try {
        Vehicle::setRoute(id_, edges);
    } catch (const libsumo::TraCIException& e) {
        throw CommandRefused(e.what());
    }
}

}  // namespace sbsim::traffic
