#include "sbsim/traffic/NetworkController.h"

#include <libsumo/Edge.h>
#include <libsumo/Lane.h>
#include <libsumo/Route.h>
#include <libsumo/Simulation.h>
#include <libsumo/TraCIDefs.h>
#include <libsumo/TrafficLight.h>
#include <libsumo/Vehicle.h>

#include <algorithm>

#include "sbsim/traffic/SumoBridge.h"
#include "sbsim/traffic/SumoRouteChecks.h"

namespace sbsim::traffic {

namespace {

/// Whether asking libsumo about an object succeeds (libsumo throws for unknown ids).
template <typename F>
bool known(F ask) {
    try {
        ask();
        return true;
    } catch (const libsumo::TraCIException&) {
        return false;
    }
}

}  // namespace

bool NetworkController::hasEdge(const std::string& edge) const {
    return known([&] { libsumo::Edge::getLaneNumber(edge); });
}

std::vector<std::string> NetworkController::lanes(const std::string& edge) const {
    const int n = libsumo::Edge::getLaneNumber(edge);
    std::vector<std::string> out;
    for (int i = 0; i < n; ++i) out.push_back(edge + "_" + std::to_string(i));
    return out;
}

LanePermissions NetworkController::permissions(const std::string& lane) const {
    return {libsumo::Lane::getAllowed(lane), libsumo::Lane::getDisallowed(lane)};
}

void NetworkController::setPermissions(const std::string& lane, const LanePermissions& recorded) {
    // A lane open to every class reports no disallowed class: "disallow nothing" gives SUMO's
    // "all" back exactly (the list of allowed class names would leave out classes SUMO does not name).
    if (recorded.disallowed.empty()) {
        libsumo::Lane::setDisallowed(lane, std::vector<std::string>{});
    } else {
        libsumo::Lane::setAllowed(lane, recorded.allowed);
    }
}

void NetworkController::closeLane(const std::string& lane) {
    libsumo::Lane::setDisallowed(lane, std::vector<std::string>{"all"});
}

bool NetworkController::routeChecks() const { return sumoRouteChecks(); }
void NetworkController::setRouteChecks(bool on) { setSumoRouteChecks(on); }

std::vector<std::string> NetworkController::knownVehicles() const { return libsumo::Vehicle::getLoadedIDList(); }
std::vector<std::string> NetworkController::loadedVehicles() const { return libsumo::Simulation::getLoadedIDList(); }
std::vector<std::string> NetworkController::departedVehicles() const {
    return libsumo::Simulation::getDepartedIDList();
}
bool NetworkController::routeValid(const std::string& vehicle) const { return libsumo::Vehicle::isRouteValid(vehicle); }
bool NetworkController::routedBySumo(const std::string& vehicle) const {
    return libsumo::Vehicle::getParameter(vehicle, "has.rerouting.device") == "true";
}
bool NetworkController::hasDeparted(const std::string& id) const {
    return libsumo::Vehicle::getDeparture(id) != libsumo::INVALID_DOUBLE_VALUE;
}
bool NetworkController::hasVehicle(const std::string& id) const {
    return known([&] { libsumo::Vehicle::getTypeID(id); });
}
std::vector<std::string> NetworkController::route(const std::string& vehicle) const {
    return libsumo::Vehicle::getRoute(vehicle);
}
int NetworkController::routeIndex(const std::string& vehicle) const { return libsumo::Vehicle::getRouteIndex(vehicle); }
std::string NetworkController::vehicleType(const std::string& vehicle) const {
    return libsumo::Vehicle::getTypeID(vehicle);
}
std::vector<std::string> NetworkController::findRoute(const std::string& from, const std::string& to,
                                                      const std::string& typeId) const {
    try {
        return libsumo::Simulation::findRoute(from, to, typeId).edges;
    } catch (const libsumo::TraCIException&) {
        return {};  // e.g. `from` lets no vehicle of the type depart: no route
    }
}
void NetworkController::reroute(const std::string& vehicle) { libsumo::Vehicle::rerouteTraveltime(vehicle); }
void NetworkController::removeVehicle(const std::string& vehicle) {
    libsumo::Vehicle::remove(vehicle);
    if (sumo_ != nullptr) sumo_->removedByCommand(vehicle);
}
bool NetworkController::hasRoute(const std::string& routeId) const {
    return known([&] { libsumo::Route::getEdges(routeId); });
}
void NetworkController::addRoute(const std::string& routeId, const std::vector<std::string>& edges) {
    libsumo::Route::add(routeId, edges);
}
void NetworkController::addVehicle(const VehicleSpawn& spawn) {
    libsumo::Vehicle::add(spawn.id, spawn.routeId, spawn.typeId, "now", spawn.departLane, spawn.departPos,
                          spawn.departSpeed);
}

bool NetworkController::hasTrafficLight(const std::string& tls) const {
    return known([&] { libsumo::TrafficLight::getProgram(tls); });
}
std::string NetworkController::signalState(const std::string& tls) const {
    return libsumo::TrafficLight::getRedYellowGreenState(tls);
}
std::string NetworkController::program(const std::string& tls) const { return libsumo::TrafficLight::getProgram(tls); }
int NetworkController::phase(const std::string& tls) const { return libsumo::TrafficLight::getPhase(tls); }
void NetworkController::setSignalState(const std::string& tls, const std::string& state) {
    libsumo::TrafficLight::setRedYellowGreenState(tls, state);
}
void NetworkController::setProgram(const std::string& tls, const std::string& programId) {
    libsumo::TrafficLight::setProgram(tls, programId);
}
void NetworkController::setPhase(const std::string& tls, int phase) { libsumo::TrafficLight::setPhase(tls, phase); }

}  // namespace sbsim::traffic
