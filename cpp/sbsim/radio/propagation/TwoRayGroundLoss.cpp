#include "sbsim/radio/propagation/TwoRayGroundLoss.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "sbsim/radio/SpeedOfLight.h"
#include "sbsim/radio/propagation/PathLossModels.h"

namespace sbsim::radio {

TwoRayGroundLoss::TwoRayGroundLoss(double frequencyHz, double transmitterHeight, double receiverHeight)
    : freeSpace_(frequencyHz) {
    if (!(transmitterHeight > 0) || !(receiverHeight > 0))
        throw std::invalid_argument("two-ray ground loss: antenna heights must be > 0 m");
    heightsDb_ = 20 * std::log10(transmitterHeight * receiverHeight);
    crossover_ = 4 * std::numbers::pi * transmitterHeight * receiverHeight * frequencyHz / kSpeedOfLight;
}

double TwoRayGroundLoss::lossDb(double distance) const {
    const double d = std::max(distance, 1.0);
    if (d < crossover_) return freeSpace_.lossDb(d);
    return 40 * std::log10(d) - heightsDb_;
}

namespace {
// Both antennas at one height.
[[maybe_unused]] const bool registered = PathLossModels::add(
    "two-ray-ground", {{"antenna_height", 1.5}}, [](double frequencyHz, const PathLossModels::Keys& keys) {
        return std::make_unique<TwoRayGroundLoss>(frequencyHz, keys.at("antenna_height"), keys.at("antenna_height"));
    });
}  // namespace

}  // namespace sbsim::radio
