#pragma once

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::radio::geonet {

/// Contention-based forwarding's timer (EN 302 636-4-1 Annex F.3; Vanetza's Router::timeout_cbf):
/// a receiver waits the longer the closer it is to the last forwarder, so the farthest one
/// rebroadcasts first and the others, hearing it, give up.
struct SBSIM_API CbfTimeout {
    kernel::SimTime minTime = kernel::SimTime::fromMilliseconds(1);    ///< TO_CBF_MIN
    kernel::SimTime maxTime = kernel::SimTime::fromMilliseconds(100);  ///< TO_CBF_MAX
    double maxDistance = 1000;  ///< DIST_MAX, m (itsGnDefaultMaxCommunicationRange)

    /// maxTime at distance 0 (and below), falling linearly to minTime at maxDistance, minTime
    /// beyond; rounded to the nanosecond (the endpoints exact).
    kernel::SimTime operator()(double distance) const;
};

}  // namespace sbsim::radio::geonet
