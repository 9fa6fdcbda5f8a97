#pragma once

#include "sbsim/radio/propagation/FreeSpaceLoss.h"
#include "sbsim/radio/propagation/PathLoss.h"

namespace sbsim::radio {

/// The two-ray ground model as ns-2 uses it: free space up to the crossover distance
/// 4π ht hr / λ, beyond it 40 log10 d − 20 log10(ht hr) (the ground reflection's d⁴ law).
class SBSIM_API TwoRayGroundLoss : public BatchedPathLoss<TwoRayGroundLoss> {
public:
    TwoRayGroundLoss(double frequencyHz, double transmitterHeight, double receiverHeight);
    double lossDb(double distance) const override;
    double crossoverDistance() const { return crossover_; }

private:
    FreeSpaceLoss freeSpace_;
    double heightsDb_;  // 20 log10(ht hr)
    double crossover_;
};

}  // namespace sbsim::radio
