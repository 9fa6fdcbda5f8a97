#include "sbsim/radio/propagation/ThreeGppHighwayLoss.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sbsim::radio {

ThreeGppHighwayLoss::ThreeGppHighwayLoss(double frequencyHz) {
    if (!(frequencyHz > 0)) throw std::invalid_argument("3GPP highway: the frequency must be > 0 Hz");
    constantDb_ = 32.4 + 20 * std::log10(frequencyHz / 1e9);
}

double ThreeGppHighwayLoss::lossDb(double distance) const {
    return constantDb_ + 20 * std::log10(std::max(distance, 1.0));
}

}  // namespace sbsim::radio
