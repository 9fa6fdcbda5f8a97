#include "sbsim/radio/FixedStations.h"

#include <stdexcept>

namespace sbsim::radio {

void FixedStations::add(std::string id, const Eigen::Vector2d& position) {
    if (id.empty()) throw std::invalid_argument("a stationary station needs an id");
    if (!position.allFinite()) throw std::invalid_argument("stationary station '" + id + "' has no finite position");
    if (index_.count(id) != 0) throw std::invalid_argument("two stationary stations are called '" + id + "'");
    index_.emplace(id, size());
    positions_.conservativeResize(Eigen::NoChange, positions_.cols() + 1);
    positions_.col(positions_.cols() - 1) = position;
    ids_.push_back(std::move(id));
}

std::optional<FixedStations::Index> FixedStations::indexOf(std::string_view id) const {
    const auto it = index_.find(std::string(id));
    if (it == index_.end()) return std::nullopt;
    return it->second;
}

}  // namespace sbsim::radio
