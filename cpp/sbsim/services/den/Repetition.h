#pragma once

#include "sbsim/kernel/SimTime.h"

namespace sbsim::services {

/// GeoNetworking's repetition of a DENM: sent again every `interval` while less than `duration`
/// passed since the first (so duration / interval sends in all).
struct Repetition {
    kernel::SimTime interval;
    kernel::SimTime duration;
};

}  // namespace sbsim::services
