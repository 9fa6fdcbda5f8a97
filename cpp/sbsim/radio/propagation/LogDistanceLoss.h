#pragma once

#include "sbsim/radio/propagation/PathLoss.h"

namespace sbsim::radio {

/// Log-distance loss: PL(d0) + 10 n log10(d / d0), with PL(d0) the reference loss at d0.
class SBSIM_API LogDistanceLoss : public BatchedPathLoss<LogDistanceLoss> {
public:
    LogDistanceLoss(double referenceLossDb, double referenceDistance, double exponent);
    double lossDb(double distance) const override;

private:
    double referenceLossDb_, referenceDistance_, exponent_;
};

}  // namespace sbsim::radio
