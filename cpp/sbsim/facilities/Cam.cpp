#include "sbsim/facilities/Cam.h"

#include "sbsim/facilities/StationRegistry.h"

namespace sbsim::facilities {

std::size_t Cam::byteSize() const {
    if (content_.stationType == StationType::RoadSideUnit) return kRoadSideUnitBytes;
    std::size_t bytes = kHighFrequencyBytes;
    if (content_.lowFrequency) bytes += 4 + 7 * content_.lowFrequency->pathHistory.size();
    return bytes;
}

void Cam::store(StationRegistry& stations, const std::string& station, kernel::SimTime now) const {
    stations.of(station).ldm.update(content_, now);
}

}  // namespace sbsim::facilities
