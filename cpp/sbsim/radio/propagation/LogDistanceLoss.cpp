#include "sbsim/radio/propagation/LogDistanceLoss.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sbsim::radio {

LogDistanceLoss::LogDistanceLoss(double referenceLossDb, double referenceDistance, double exponent)
    : referenceLossDb_(referenceLossDb), referenceDistance_(referenceDistance), exponent_(exponent) {
    if (!(referenceDistance > 0))
        throw std::invalid_argument("log-distance loss: the reference distance must be > 0 m");
    if (!(exponent > 0)) throw std::invalid_argument("log-distance loss: the exponent must be > 0");
}

double LogDistanceLoss::lossDb(double distance) const {
    return referenceLossDb_ + 10 * exponent_ * std::log10(std::max(distance, 1.0) / referenceDistance_);
}

}  // namespace sbsim::radio
