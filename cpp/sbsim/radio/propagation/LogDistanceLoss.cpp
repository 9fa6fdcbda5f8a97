#include "sbsim/radio/propagation/LogDistanceLoss.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "sbsim/radio/propagation/PathLossModels.h"

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

namespace {
// Reference: free space at 1 m and 5.89 GHz.
[[maybe_unused]] const bool registered =
    PathLossModels::add("log-distance", {{"reference_loss_db", 47.86}, {"reference_distance", 1}, {"exponent", 2.0}},
                        [](double, const PathLossModels::Keys& keys) {
                            return std::make_unique<LogDistanceLoss>(
                                keys.at("reference_loss_db"), keys.at("reference_distance"), keys.at("exponent"));
                        });
}  // namespace

}  // namespace sbsim::radio
