#pragma once

#include "sbsim/radio/propagation/PathLoss.h"

namespace sbsim::radio {

/// Friis free-space loss: 20 log10(4π d f / c).
class SBSIM_API FreeSpaceLoss : public BatchedPathLoss<FreeSpaceLoss> {
public:
    explicit FreeSpaceLoss(double frequencyHz);
    double lossDb(double distance) const override;

private:
    double constantDb_;  // 20 log10(4π f / c)
};

}  // namespace sbsim::radio
