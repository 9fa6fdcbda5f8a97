#pragma once

#include "sbsim/radio/propagation/PathLoss.h"

namespace sbsim::radio {

/// 3GPP TR 37.885 (V2X evaluation methodology) Table 6.2.1-1, highway, line of sight:
/// 32.4 + 20 log10 d + 20 log10 f_GHz (d the 3D distance, equal to the 2D one for antennas of equal
/// height). The table's companions: σ = 3 dB shadowing, decorrelation 25 m (WiLabV2Xsim's highway).
class SBSIM_API ThreeGppHighwayLoss : public BatchedPathLoss<ThreeGppHighwayLoss> {
public:
    /// Throws std::invalid_argument for a frequency not > 0.
    explicit ThreeGppHighwayLoss(double frequencyHz);
    double lossDb(double distance) const override;

private:
    double constantDb_;  // 32.4 + 20 log10 f_GHz
};

}  // namespace sbsim::radio
