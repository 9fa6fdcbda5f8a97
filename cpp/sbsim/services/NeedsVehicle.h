#pragma once

#include <string_view>

#include "sbsim/kernel/Export.h"

namespace sbsim::services {

/// A service that needs a vehicle of its own (its speed, heading, commands) derives from this too:
/// a roadside unit refuses it when it is made, saying why, rather than host one that never acts. A
/// mix-in, as facilities::ItsMessageHandler, so that Service keeps the layout modules were built for.
class SBSIM_API NeedsVehicle {
public:
    virtual ~NeedsVehicle() = default;
    /// Why, in a clause the refusal quotes; empty for a subclass that runs on a unit after all.
    virtual std::string_view whyVehicle() const = 0;
};

}  // namespace sbsim::services
