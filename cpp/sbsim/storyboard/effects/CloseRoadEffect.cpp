#include "sbsim/storyboard/effects/CloseRoadEffect.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"

namespace sbsim::storyboard {

CloseRoadEffect::CloseRoadEffect(std::vector<std::string> edges) : edges_(std::move(edges)) {
    if (edges_.empty()) throw std::invalid_argument("CloseRoadEffect needs at least one edge id");
    for (const std::string& e : edges_) {
        if (e.empty()) throw std::invalid_argument("CloseRoadEffect: an edge id is empty");
    }
}

std::string CloseRoadEffect::describe() const { return fmt::format("CloseRoadEffect({})", fmt::join(edges_, ", ")); }

void CloseRoadEffect::check(CheckContext& ctx) const { ctx.warnUnknown(typeName(), NetworkObject::Edge, edges_); }

}  // namespace sbsim::storyboard
