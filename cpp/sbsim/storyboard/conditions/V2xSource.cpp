#include "sbsim/storyboard/conditions/V2xSource.h"

namespace sbsim::storyboard {

namespace {
std::shared_ptr<const facilities::StationRegistry>& slot() {
    static std::shared_ptr<const facilities::StationRegistry> stations;
    return stations;
}
}  // namespace

void V2xSource::use(std::shared_ptr<const facilities::StationRegistry> stations) { slot() = std::move(stations); }

std::shared_ptr<const facilities::StationRegistry> V2xSource::current() {
    if (!slot()) slot() = std::make_shared<const facilities::StationRegistry>();
    return slot();
}

}  // namespace sbsim::storyboard
