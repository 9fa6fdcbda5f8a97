#include "sbsim/radio/propagation/ThreeGppHighwayLoss.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "sbsim/radio/propagation/PathLossModels.h"

namespace sbsim::radio {

ThreeGppHighwayLoss::ThreeGppHighwayLoss(double frequencyHz) {
    if (!(frequencyHz > 0)) throw std::invalid_argument("3GPP highway: the frequency must be > 0 Hz");
    constantDb_ = 32.4 + 20 * std::log10(frequencyHz / 1e9);
}

double ThreeGppHighwayLoss::lossDb(double distance) const {
    return constantDb_ + 20 * std::log10(std::max(distance, 1.0));
}

namespace {
[[maybe_unused]] const bool registered = PathLossModels::add(
    "3gpp-highway", {},
    [](double frequencyHz, const PathLossModels::Keys&) { return std::make_unique<ThreeGppHighwayLoss>(frequencyHz); });
}  // namespace

}  // namespace sbsim::radio
