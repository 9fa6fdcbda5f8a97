#include "sbsim/radio/propagation/FreeSpaceLoss.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "sbsim/radio/SpeedOfLight.h"
#include "sbsim/radio/propagation/PathLossModels.h"

namespace sbsim::radio {

FreeSpaceLoss::FreeSpaceLoss(double frequencyHz) {
    if (!(frequencyHz > 0)) throw std::invalid_argument("free-space loss: the frequency must be > 0 Hz");
    constantDb_ = 20 * std::log10(4 * std::numbers::pi * frequencyHz / kSpeedOfLight);
}

double FreeSpaceLoss::lossDb(double distance) const { return 20 * std::log10(std::max(distance, 1.0)) + constantDb_; }

namespace {
[[maybe_unused]] const bool registered = PathLossModels::add(
    "free-space", {},
    [](double frequencyHz, const PathLossModels::Keys&) { return std::make_unique<FreeSpaceLoss>(frequencyHz); });
}  // namespace

}  // namespace sbsim::radio
