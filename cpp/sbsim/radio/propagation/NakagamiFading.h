#pragma once

#include "sbsim/kernel/Export.h"
#include "sbsim/radio/CounterRandom.h"

namespace sbsim::radio {

/// Nakagami-m small-scale fading of the received power: the power is Gamma(m, mean/m)
/// distributed, so its mean is the path-loss power. Either one m for every link, or Veins'
/// distance rule (m = 1.5 below 80 m, 0.75 beyond).
struct SBSIM_API NakagamiFading {
    double m = 1.5;
    bool veinsDistanceRule = false;

    double shapeAt(double distance) const { return veinsDistanceRule ? (distance < 80 ? 1.5 : 0.75) : m; }
    /// The fading gain in dB (mean 1 in linear power) for one link and message.
    double gainDb(double distance, CounterRandom& random) const;
};

}  // namespace sbsim::radio
