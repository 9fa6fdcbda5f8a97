#include "sbsim/radio/propagation/ThreeGppUrbanLoss.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "sbsim/radio/propagation/PathLossModels.h"

namespace sbsim::radio {

ThreeGppUrbanLoss::ThreeGppUrbanLoss(double frequencyHz, bool lineOfSight) {
    if (!(frequencyHz > 0)) throw std::invalid_argument("3GPP urban: the frequency must be > 0 Hz");
    const double logF = std::log10(frequencyHz / 1e9);
    constantDb_ = lineOfSight ? 38.77 + 18.2 * logF : 36.85 + 18.9 * logF;
    slopeDb_ = lineOfSight ? 16.7 : 30;
}

double ThreeGppUrbanLoss::lossDb(double distance) const {
    return constantDb_ + slopeDb_ * std::log10(std::max(distance, 1.0));
}

namespace {
[[maybe_unused]] const bool registeredLos =
    PathLossModels::add("3gpp-urban", {}, [](double frequencyHz, const PathLossModels::Keys&) {
        return std::make_unique<ThreeGppUrbanLoss>(frequencyHz, true);
    });
[[maybe_unused]] const bool registeredNlos =
    PathLossModels::add("3gpp-urban-nlos", {}, [](double frequencyHz, const PathLossModels::Keys&) {
        return std::make_unique<ThreeGppUrbanLoss>(frequencyHz, false);
    });
}  // namespace

}  // namespace sbsim::radio
