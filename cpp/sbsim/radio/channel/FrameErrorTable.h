#pragma once

#include <utility>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::radio {

/// Frame error rate against Eb/N0 for one data rate: points (Eb/N0 in dB, FER), interpolated
/// linearly in dB on both axes (log10 of the FER), so the decades between points fall smoothly.
/// Below the first point the FER is the first point's, above the last the last's.
class SBSIM_API FrameErrorTable {
public:
    /// Throws std::invalid_argument unless there is a point, Eb/N0 ascends strictly and every
    /// FER is in (0, 1].
    explicit FrameErrorTable(std::vector<std::pair<double, double>> points);

    /// The 6 Mbit/s table of Goubet et al. (IEEE TVT 2015) that Sepulcre et al. use: 0 dB → 1,
    /// 5 → 1, 10 → 0.4, 15 → 1.5e-2, 20 → 4e-3, 25 → 3e-3, 30 → 2e-3, 35 → 1e-3.
    static FrameErrorTable goubet6Mbps();

    double ferAtEbN0Db(double ebN0Db) const;
    /// FER at `sinrDb` for a channel `bandwidthHz` wide carrying `rateBps`: Eb/N0 = SINR · B / R.
    double fer(double sinrDb, double bandwidthHz, double rateBps) const;
    /// The points as given (FER, not its logarithm).
    const std::vector<std::pair<double, double>>& points() const { return given_; }

private:
    std::vector<std::pair<double, double>> points_;  // (Eb/N0 dB, log10 FER)
    std::vector<std::pair<double, double>> given_;
};

}  // namespace sbsim::radio
