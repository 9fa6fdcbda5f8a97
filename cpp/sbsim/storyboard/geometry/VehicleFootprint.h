#pragma once

#include "sbsim/storyboard/geometry/Footprint.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::storyboard::geometry {

/// Vehicle `i`'s footprint in `snapshot` (its front bumper, angle, length and width).
inline Footprint footprintOf(const traffic::VehicleSnapshot& snapshot, traffic::VehicleSnapshot::Index i) {
    return Footprint::fromSumo(snapshot.positions().col(i), snapshot.angles()[i], snapshot.lengths()[i],
                               snapshot.widths()[i]);
}

}  // namespace sbsim::storyboard::geometry
