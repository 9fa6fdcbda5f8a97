#pragma once

#include <memory>

#include "sbsim/facilities/StationRegistry.h"
#include "sbsim/kernel/Export.h"

namespace sbsim::storyboard {

/// Where the V2X conditions (DenmCondition, CamCondition) read what the stations heard: the run's
/// station registry, which the app sets before the story script creates conditions (they keep the
/// one current at their creation). Without one they read an empty registry: never true.
class SBSIM_API V2xSource {
public:
    static void use(std::shared_ptr<const facilities::StationRegistry> stations);
    static std::shared_ptr<const facilities::StationRegistry> current();
};

}  // namespace sbsim::storyboard
