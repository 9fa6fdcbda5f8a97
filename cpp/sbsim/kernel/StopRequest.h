#pragma once

#include "sbsim/kernel/Export.h"

namespace sbsim::kernel {

/// Whether the program was asked to stop (SIGINT, SIGTERM): set by the program's signal handler,
/// read by long loops in any layer (a condition's sampling, a step's evaluation) so that they give
/// up at their next safe point instead of finishing work the run will throw away.
class SBSIM_API StopRequest {
public:
    /// Async-signal-safe (a lock-free atomic store).
    static void request() noexcept;
    static bool requested() noexcept;
    /// For tests: forget a request.
    static void clear() noexcept;
};

}  // namespace sbsim::kernel
