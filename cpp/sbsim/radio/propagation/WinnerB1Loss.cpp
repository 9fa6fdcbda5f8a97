#include "sbsim/radio/propagation/WinnerB1Loss.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "sbsim/radio/SpeedOfLight.h"
#include "sbsim/radio/propagation/PathLossModels.h"

namespace sbsim::radio {

WinnerB1Loss::WinnerB1Loss(double frequencyHz, double antennaHeight, double environmentHeight) {
    const double effective = antennaHeight - environmentHeight;
    if (!(frequencyHz > 0)) throw std::invalid_argument("WINNER+ B1: the frequency must be > 0 Hz");
    if (!(effective > 0)) throw std::invalid_argument("WINNER+ B1: antennas must be above the environment height");
    breakpoint_ = 4 * effective * effective * frequencyHz / kSpeedOfLight;
    const double ghz = frequencyHz / 1e9;
    nearDb_ = 27 + 20 * std::log10(ghz);
    farDb_ = 7.56 + 2.7 * std::log10(ghz);
    freeSpaceDb_ = 46.4 + 20 * std::log10(ghz / 5.0);
}

double WinnerB1Loss::lossDb(double distance) const {
    const double d = std::max(distance, 1.0);
    const double logD = std::log10(d);
    const double winner = d < breakpoint_ ? 22.7 * logD + nearDb_ : 40 * logD + farDb_;
    return std::max(winner, 20 * logD + freeSpaceDb_);
}

namespace {
[[maybe_unused]] const bool registered = PathLossModels::add(
    "winner-b1", {{"antenna_height", 1.5}, {"environment_height", 0.5}},
    [](double frequencyHz, const PathLossModels::Keys& keys) {
        return std::make_unique<WinnerB1Loss>(frequencyHz, keys.at("antenna_height"), keys.at("environment_height"));
    });
}  // namespace

}  // namespace sbsim::radio
