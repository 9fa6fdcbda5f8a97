#pragma once

#include "sbsim/kernel/Export.h"

namespace sbsim::radio {

/// A deterministic (mean) path-loss law: what a link loses over `distance` metres in free air,
/// before shadowing, fading and obstacles. Evaluated for every link of every transmission, so
/// implementations are small, const and thread-safe.
class SBSIM_API PathLoss {
public:
    virtual ~PathLoss() = default;
    /// Loss in dB at `distance` m (> 0; distances below 1 m are taken as 1 m).
    virtual double lossDb(double distance) const = 0;
};

}  // namespace sbsim::radio
