#include "traffic/VehicleSnapshot.h"

#include <algorithm>

namespace sbsim::traffic {

std::optional<VehicleSnapshot::Index> VehicleSnapshot::indexOf(std::string_view id) const {
    const auto it = std::lower_bound(ids_.begin(), ids_.end(), id,
                                     [](const std::string& a, std::string_view b) { return std::string_view(a) < b; });
    if (it == ids_.end() || *it != id) return std::nullopt;
    return static_cast<Index>(it - ids_.begin());
}

}  // namespace sbsim::traffic
