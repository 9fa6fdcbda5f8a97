#include "sbsim/radio/propagation/FreeSpaceLoss.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sbsim/radio/SpeedOfLight.h"

namespace sbsim::radio {

FreeSpaceLoss::FreeSpaceLoss(double frequencyHz) {
    if (!(frequencyHz > 0)) throw std::invalid_argument("free-space loss: the frequency must be > 0 Hz");
    constantDb_ = 20 * std::log10(4 * std::numbers::pi * frequencyHz / kSpeedOfLight);
}

double FreeSpaceLoss::lossDb(double distance) const { return 20 * std::log10(std::max(distance, 1.0)) + constantDb_; }

}  // namespace sbsim::radio
