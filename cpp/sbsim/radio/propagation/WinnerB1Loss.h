#pragma once

#include "sbsim/radio/propagation/PathLoss.h"

namespace sbsim::radio {

/// WINNER+ B1 (urban micro-cell) line of sight, as Sepulcre et al. (IEEE TVT 2022) use it for
/// V2V: breakpoint d_BP = 4 (h − h_E)² f / c for both antennas at h with environment height h_E;
/// below it 22.7 log10 d + 27 + 20 log10 f_GHz, at or above 40 log10 d + 7.56 + 2.7 log10 f_GHz
/// (the standard's form with h − h_E = 1 m), and never less than free space
/// 20 log10 d + 46.4 + 20 log10(f / 5 GHz).
class SBSIM_API WinnerB1Loss : public BatchedPathLoss<WinnerB1Loss> {
public:
    WinnerB1Loss(double frequencyHz, double antennaHeight, double environmentHeight);
    double lossDb(double distance) const override;
    double breakpoint() const { return breakpoint_; }

private:
    double breakpoint_;
    double nearDb_, farDb_, freeSpaceDb_;  // the frequency terms of the three laws
};

}  // namespace sbsim::radio
