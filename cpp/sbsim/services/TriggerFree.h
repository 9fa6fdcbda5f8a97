#pragma once

#include "sbsim/kernel/Export.h"

namespace sbsim::services {

/// A service whose trigger() does nothing derives from this too (BeaconService: its own timer sends).
/// A station all of whose services do is not woken every interval for them: its middleware's clock
/// runs only while its facilities hold something to expire (Middleware). A service without it is
/// triggered every interval, as before. (A mix-in, as IndicatedTypes, so that service modules built
/// against an older Service keep their layout.)
class SBSIM_API TriggerFree {
public:
    virtual ~TriggerFree() = default;
};

}  // namespace sbsim::services
