#include "sbsim/radio/geonet/CbfTimeout.h"

#include <cmath>

namespace sbsim::radio::geonet {

kernel::SimTime CbfTimeout::operator()(double distance) const {
    if (!(distance > 0)) return maxTime;  // also NaN: no progress known
    if (distance >= maxDistance) return minTime;
    const double fall = static_cast<double>((maxTime - minTime).raw()) * (distance / maxDistance);
    return maxTime - kernel::SimTime::fromRaw(std::llround(fall));
}

}  // namespace sbsim::radio::geonet
