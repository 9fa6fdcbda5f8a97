#pragma once

#include "sbsim/facilities/DenmMemory.h"
#include "sbsim/facilities/LocalDynamicMap.h"

namespace sbsim::facilities {

/// What one station's facilities keep of what it heard.
struct StationFacilities {
    LocalDynamicMap ldm;
    DenmMemory denms;

    /// Whether it holds nothing (nothing can expire).
    bool empty() const { return ldm.size() == 0 && denms.size() == 0; }

    /// Drops what expired before `now` (LDM entries and DENM events); the events dropped are returned.
    std::vector<DenmMemory::Entry> dropExpired(kernel::SimTime now) {
        ldm.dropExpired(now);
        return denms.dropExpired(now);
    }
};

}  // namespace sbsim::facilities
