#include "sbsim/storyboard/effects/RouteEffect.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"

namespace sbsim::storyboard {

RouteEffect::RouteEffect(std::optional<std::string> targetEdge, std::vector<std::string> via, bool keep)
    : route_{std::move(targetEdge), std::move(via)}, keep_(keep) {
    if (keep_ && !route_.target && route_.via.empty())
        throw std::invalid_argument("RouteEffect needs a target edge or via edges");
    if (!keep_ && route_.target.has_value() == !route_.via.empty())
        throw std::invalid_argument("RouteEffect needs either a target edge or via edges, not both or neither");
    const auto empty = [](const std::string& edge) { return edge.empty(); };
    if ((route_.target && route_.target->empty()) || std::any_of(route_.via.begin(), route_.via.end(), empty))
        throw std::invalid_argument("RouteEffect: an edge id is empty");
}

void RouteEffect::apply(EffectScope& scope) {
    if (!keep_) {
        scope.stack().pushRoute(scope.token(), route_);
        return;
    }
    traffic::VehicleController& vehicle = scope.vehicle();
    // The edge it stands on needs no passing (SUMO routes from there).
    const std::string road = vehicle.roadId();
    std::vector<std::string> via;
    for (const std::string& edge : route_.via) {
        if (edge != road) via.push_back(edge);
    }
    std::optional<std::string> target = route_.target;
    if (!target) {
        const std::vector<std::string> edges = vehicle.route();
        if (!edges.empty()) target = edges.back();
    }
    vehicle.setVia(via);
    if (target) vehicle.changeTarget(*target);
}

std::string RouteEffect::describe() const {
    std::string s = route_.target ? fmt::format("RouteEffect(to {}", *route_.target) : "RouteEffect(";
    if (!route_.via.empty()) s += fmt::format("{}via {}", route_.target ? ", " : "", fmt::join(route_.via, ", "));
    return s + (keep_ ? ", kept)" : ")");
}

void RouteEffect::check(CheckContext& ctx) const {
    std::vector<std::string> edges = route_.via;
    if (route_.target) edges.insert(edges.begin(), *route_.target);
    ctx.warnUnknown(typeName(), NetworkObject::Edge, edges);
}

}  // namespace sbsim::storyboard
