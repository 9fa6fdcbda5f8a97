#pragma once

#include <cstdint>

namespace sbsim::radio {

/// One receiver of one frame: what the link budget computed when the frame started, and what
/// reception learns while it is on the air.
struct Link {
    std::int32_t receiver = -1;  // the station's slot
    std::uint32_t bin = 0;       // distance / Medium::kDistanceBin, for the link counts
    std::int32_t cell = -1;      // the receiver's far-tier cell this step (FarCells), -1 = none
    double distance = 0;
    double powerDbm = 0;
    double powerMw = 0;
    double maxInterferenceMw = 0;  // the largest sum of the other frames overlapping this one
    bool counted = false;          // above the floor: part of the receiver's sensed power
    bool halfDuplex = false;       // the receiver transmitted during the frame
    bool locked = false;           // the receiver was decoding this frame
};

}  // namespace sbsim::radio
