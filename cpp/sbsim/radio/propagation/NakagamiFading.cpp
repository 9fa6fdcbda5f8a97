#include "sbsim/radio/propagation/NakagamiFading.h"

#include <cmath>

namespace sbsim::radio {

double NakagamiFading::gainDb(double distance, CounterRandom& random) const {
    const double shape = shapeAt(distance);
    const double linear = random.gamma(shape) / shape;
    return 10 * std::log10(std::max(linear, 1e-30));
}

}  // namespace sbsim::radio
