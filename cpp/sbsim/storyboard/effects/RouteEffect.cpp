#include "sbsim/storyboard/effects/RouteEffect.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"

namespace sbsim::storyboard {

RouteEffect::RouteEffect(std::optional<std::string> targetEdge, std::vector<std::string> via)
    : route_{std::move(targetEdge), std::move(via)} {
    if (route_.target.has_value() == !route_.via.empty())
        throw std::invalid_argument("RouteEffect needs either a target edge or via edges, not both or neither");
    const auto empty = [](const std::string& edge) { return edge.empty(); };
    if ((route_.target && route_.target->empty()) || std::any_of(route_.via.begin(), route_.via.end(), empty))
        throw std::invalid_argument("RouteEffect: an edge id is empty");
}

std::string RouteEffect::describe() const {
    return route_.target ? fmt::format("RouteEffect(to {})", *route_.target)
                         : fmt::format("RouteEffect(via {})", fmt::join(route_.via, ", "));
}

void RouteEffect::check(CheckContext& ctx) const {
    ctx.warnUnknown(typeName(), NetworkObject::Edge, route_.target ? std::vector{*route_.target} : route_.via);
}

}  // namespace sbsim::storyboard
