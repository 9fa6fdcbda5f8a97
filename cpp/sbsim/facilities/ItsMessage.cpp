#include "sbsim/facilities/ItsMessage.h"

#include "sbsim/facilities/StationRegistry.h"

namespace sbsim::facilities {

void ItsMessage::store(StationRegistry& stations, std::string_view station, kernel::SimTime now) const {
    store(stations, stations.intern(station), now);
}

}  // namespace sbsim::facilities
