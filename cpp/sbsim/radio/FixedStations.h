#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::radio {

/// The stationary stations (roadside units) a medium knows beside the snapshot's vehicles: ids
/// and fixed positions, struct-of-arrays, in the order they were added, which is the order a
/// medium visits them in (after the vehicles, so a run without any finds every vehicle as before).
/// A scenario has a few, not thousands: searched linearly rather than through a grid.
class SBSIM_API FixedStations {
public:
    using Index = std::int32_t;

    /// Throws std::invalid_argument for an empty or duplicate id or a position that is not finite.
    void add(std::string id, const Eigen::Vector2d& position);

    Index size() const { return static_cast<Index>(ids_.size()); }
    bool empty() const { return ids_.empty(); }
    const std::vector<std::string>& ids() const { return ids_; }
    /// Column k: station k's position, SUMO network frame (m).
    const Eigen::Matrix2Xd& positions() const { return positions_; }
    std::optional<Index> indexOf(std::string_view id) const;

    /// Calls `visit(k, distance)` for every station k other than `skip` within `radius` m
    /// (inclusive) of `point`, k ascending.
    template <typename Visit>
    void forEachWithin(const Eigen::Vector2d& point, double radius, std::optional<Index> skip, Visit&& visit) const {
        for (Index k = 0; k < size(); ++k) {
            if (k == skip) continue;
            const double distance = (positions_.col(k) - point).norm();
            if (distance <= radius) visit(k, distance);
        }
    }

private:
    std::vector<std::string> ids_;
    Eigen::Matrix2Xd positions_{2, 0};
    std::unordered_map<std::string, Index> index_;
};

}  // namespace sbsim::radio
