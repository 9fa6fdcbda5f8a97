#include "sbsim/storyboard/effects/SpawnEffect.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/storyboard/NetworkStack.h"

namespace sbsim::storyboard {

SpawnEffect::SpawnEffect(Spec spec) : spec_(std::move(spec)) {
    if (spec_.id.empty()) throw std::invalid_argument("SpawnEffect needs a vehicle id");
    const bool fromTo = !spec_.from.empty() || !spec_.to.empty();
    if (!spec_.route.empty() && fromTo) {
        throw std::invalid_argument("SpawnEffect takes a route or from_edge and to_edge, not both");
    }
    if (spec_.route.empty() && (spec_.from.empty() || spec_.to.empty())) {
        throw std::invalid_argument("SpawnEffect needs a route (a list of edges) or both from_edge and to_edge");
    }
    // SUMO accepts a route over a junction's internal edges and then loses the vehicle silently.
    for (const std::string& edge : spec_.route.empty() ? std::vector{spec_.from, spec_.to} : spec_.route) {
        if (edge.starts_with(':')) {
            throw std::invalid_argument(fmt::format(
                "SpawnEffect: '{}' is an internal (junction) edge; a route names the network's normal edges", edge));
        }
    }
}

void SpawnEffect::apply(WorldScope& scope) {
    traffic::NetworkController& network = scope.network();
    if (network.hasVehicle(spec_.id)) throw std::invalid_argument(fmt::format("vehicle '{}' exists already", spec_.id));
    std::vector<std::string> edges = spec_.route;
    for (const std::string& e : edges.empty() ? std::vector<std::string>{spec_.from, spec_.to} : edges) {
        if (!network.hasEdge(e)) throw std::invalid_argument(fmt::format("no edge '{}' in the network", e));
    }
    traffic::VehicleSpawn spawn;
    spawn.id = spec_.id;
    if (spec_.type) spawn.typeId = *spec_.type;
    if (edges.empty()) {
        edges = network.findRoute(spec_.from, spec_.to, spawn.typeId);
        if (edges.empty()) throw std::invalid_argument(fmt::format("no route from {} to {}", spec_.from, spec_.to));
    }
    // A route id of its own: scripts' route ids and the route files' cannot collide with it.
    spawn.routeId = "sbsim:spawn:" + spec_.id;
    for (int n = 1; network.hasRoute(spawn.routeId); ++n) spawn.routeId = fmt::format("sbsim:spawn:{}#{}", spec_.id, n);
    if (spec_.lane) spawn.departLane = *spec_.lane;
    if (spec_.position) spawn.departPos = *spec_.position;
    if (spec_.speed) spawn.departSpeed = *spec_.speed;
    network.addRoute(spawn.routeId, edges);
    // SUMO checks the route as it would with no edge closed: one SUMO refuses (through a closed
    // edge, or not connected) stays an error while a closure has SUMO's route checks off.
    const bool checks = network.routeChecks();
    network.setRouteChecks(scope.stack().routeChecksOutsideClosures());
    try {
        network.addVehicle(spawn);
    } catch (...) {
        network.setRouteChecks(checks);
        throw;
    }
    network.setRouteChecks(checks);
}

std::string SpawnEffect::describe() const {
    const std::string way = spec_.route.empty() ? fmt::format("{} to {}", spec_.from, spec_.to)
                                                : fmt::format("route {}", fmt::join(spec_.route, " "));
    return fmt::format("SpawnEffect('{}', {}{})", spec_.id, way, spec_.type ? ", type " + *spec_.type : "");
}

void SpawnEffect::check(CheckContext& ctx) const {
    ctx.warnUnknown(typeName(), NetworkObject::Edge,
                    spec_.route.empty() ? std::vector{spec_.from, spec_.to} : spec_.route);
    if (spec_.type) ctx.warnUnknown(typeName(), NetworkObject::VehicleType, {*spec_.type});
}

}  // namespace sbsim::storyboard
