#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

#include "sbsim/kernel/Export.h"

namespace sbsim::radio::geonet {

/// A station a router knows around it (its location table: sbsim takes the CAMs heard).
struct Neighbour {
    std::string_view station;
    Eigen::Vector2d position;
};

/// Greedy forwarding's next hop (EN 302 636-4-1 Annex E.2, most forward within radius): the
/// neighbour nearest to `target`, if it is nearer than `self` (progress); none at a local
/// optimum. Among equally near neighbours the first given wins.
SBSIM_API std::optional<std::size_t> greedyNextHop(const Eigen::Vector2d& self, const Eigen::Vector2d& target,
                                                   std::span<const Neighbour> neighbours);

}  // namespace sbsim::radio::geonet
