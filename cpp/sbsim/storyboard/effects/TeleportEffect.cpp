#include "sbsim/storyboard/effects/TeleportEffect.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"

namespace sbsim::storyboard {

TeleportEffect::TeleportEffect(Target target, std::vector<std::string> onward)
    : target_(std::move(target)), onward_(std::move(onward)) {
    if (!std::isfinite(target_.position)) throw std::invalid_argument("TeleportEffect needs a finite position in m");
    if (target_.relativeTo) {
        if (target_.relativeTo->empty()) throw std::invalid_argument("TeleportEffect: the vehicle id is empty");
        if (!target_.edge.empty()) throw std::invalid_argument("TeleportEffect: an edge or a vehicle, not both");
        return;
    }
    if (target_.edge.empty()) throw std::invalid_argument("TeleportEffect needs an edge id");
    if (target_.lane < 0 || target_.position < 0) {
        throw std::invalid_argument(fmt::format("TeleportEffect needs a lane >= 0 and a position >= 0, got {} and {:g}",
                                                target_.lane, target_.position));
    }
    if (!onward_.empty() && onward_.front() != target_.edge)
        throw std::invalid_argument("TeleportEffect: the onward route must start on the target edge");
}

void TeleportEffect::apply(EffectScope& scope) {
    traffic::VehicleController& vehicle = scope.vehicle();
    std::string edge = target_.edge;
    int lane = target_.lane;
    double position = target_.position;
    if (target_.relativeTo) {
        const auto other = scope.controllerOf(*target_.relativeTo);
        edge = other->roadId();
        lane += other->laneIndex();
        position += other->lanePosition();
    }
    const std::string laneId = fmt::format("{}_{}", edge, lane);
    const std::vector<std::string> route = vehicle.route();
    const std::string destination = route.empty() ? std::string() : route.back();
    const bool onRoute = std::find(route.begin(), route.end(), edge) != route.end();
    if (!onRoute) vehicle.changeTarget(edge);  // SUMO moves a vehicle only along its route
    vehicle.moveTo(laneId, position);
    if (onRoute) return;  // the route it had still leads on from there
    if (!onward_.empty() && onward_.front() == edge) {
        vehicle.setRoute(onward_);
    } else if (!destination.empty() && destination != edge) {
        vehicle.changeTarget(destination);
    }
}

std::string TeleportEffect::describe() const {
    if (target_.relativeTo) {
        return fmt::format("TeleportEffect({}'s lane {:+d}, {:+g} m)", *target_.relativeTo, target_.lane,
                           target_.position);
    }
    return fmt::format("TeleportEffect({}_{} at {:g} m)", target_.edge, target_.lane, target_.position);
}

void TeleportEffect::check(CheckContext& ctx) const {
    if (!target_.edge.empty()) ctx.warnUnknown(typeName(), NetworkObject::Edge, std::vector{target_.edge});
    if (target_.relativeTo && !ctx.vehicleDefined(*target_.relativeTo)) {
        ctx.warn(fmt::format("{} is relative to vehicle '{}', which no route file or story defines", typeName(),
                             *target_.relativeTo));
    }
}

}  // namespace sbsim::storyboard
