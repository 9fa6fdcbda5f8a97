#pragma once

#include <cstdint>
#include <string_view>

#include "sbsim/kernel/Export.h"

namespace sbsim::traffic {

/// Which vehicles carry V2X equipment (--penetration): a share of them, chosen by a hash of the
/// run's seed and the vehicle id. The choice depends on nothing else — not the order vehicles
/// depart, not the thread count — so with the same seed the same vehicles are equipped in every
/// run, and raising the share only adds vehicles (a vehicle equipped at 0.3 is equipped at 0.5).
class SBSIM_API Penetration {
public:
    /// Everybody equipped (the default).
    Penetration() = default;
    /// Throws std::invalid_argument unless 0 <= share <= 1.
    Penetration(double share, std::uint64_t seed);

    double share() const { return share_; }
    bool everyone() const { return share_ >= 1.0; }
    bool equipped(std::string_view vehicleId) const;
    /// The vehicle's draw in [0, 1): it is equipped iff draw < share.
    double draw(std::string_view vehicleId) const;

private:
    double share_ = 1.0;
    std::uint64_t seed_ = 0;
};

}  // namespace sbsim::traffic
