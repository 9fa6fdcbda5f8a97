#include "sbsim/facilities/Cam.h"

#include "sbsim/facilities/StationRegistry.h"

namespace sbsim::facilities {

std::size_t Cam::byteSize() const {
    if (content_.stationType == StationType::RoadSideUnit) return kRoadSideUnitBytes;
    std::size_t bytes = kHighFrequencyBytes;
    if (content_.lowFrequency) bytes += 4 + 7 * content_.lowFrequency->pathHistory.size();
    return bytes;
}

void Cam::store(StationRegistry& stations, radio::StationIds::Index station, kernel::SimTime now) const {
    if (indexedIn_ != stations.identity()) {
        index_ = stations.intern(content_.station);
        indexedIn_ = stations.identity();
    }
    stations.of(station).ldm.update(index_, content_, now);
}

}  // namespace sbsim::facilities
