#pragma once

#include "sbsim/radio/propagation/PathLoss.h"

namespace sbsim::radio {

/// 3GPP TR 37.885 Table 6.2.1-1, urban grid (d the 3D distance, equal to the 2D one for antennas of
/// equal height):
///  - line of sight: 38.77 + 16.7 log10 d + 18.2 log10 f_GHz (σ = 3 dB, decorrelation 10 m);
///  - NLOS (a building between): 36.85 + 30 log10 d + 18.9 log10 f_GHz (σ = 4 dB, 13 m).
/// Which one applies is the radio file's choice (`3gpp-urban` or `3gpp-urban-nlos`): sbsim draws no
/// LOS state per link; with SUMO's buildings as obstacles use the LOS law and let them add the walls.
class SBSIM_API ThreeGppUrbanLoss : public BatchedPathLoss<ThreeGppUrbanLoss> {
public:
    /// Throws std::invalid_argument for a frequency not > 0.
    ThreeGppUrbanLoss(double frequencyHz, bool lineOfSight);
    double lossDb(double distance) const override;

private:
    double constantDb_, slopeDb_;
};

}  // namespace sbsim::radio
