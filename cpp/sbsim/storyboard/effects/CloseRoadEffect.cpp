#include "sbsim/storyboard/effects/CloseRoadEffect.h"

#include <stdexcept>

namespace sbsim::storyboard {

CloseRoadEffect::CloseRoadEffect(std::vector<std::string> edges) : edges_(std::move(edges)) {
    if (edges_.empty()) throw std::invalid_argument("CloseRoadEffect needs at least one edge id");
    for (const std::string& e : edges_) {
        if (e.empty()) throw std::invalid_argument("CloseRoadEffect: an edge id is empty");
    }
}

}  // namespace sbsim::storyboard
