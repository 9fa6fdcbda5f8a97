#pragma once

#include <optional>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::radio {

/// The disc model's settings (`--v2x-range`, `--v2x-latency`, `--v2x-fade-start`).
struct SBSIM_API DiscSettings {
    double range = 500;  ///< m
    kernel::SimTime latency = kernel::SimTime::fromMilliseconds(1);
    /// Packet errors: reception is certain up to this distance, then falls linearly to 0 at
    /// `range`. None (the default): no losses.
    std::optional<double> fadeStart;
    /// Lost receptions ("range", "fade") are traced for stations this close to the sender.
    double traceRange = 1000;
};

}  // namespace sbsim::radio
