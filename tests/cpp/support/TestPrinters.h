#pragma once

#include <ostream>

#include "sbsim/kernel/SimTime.h"

namespace sbsim::kernel {

/// Lets GoogleTest print times in failure messages as seconds instead of raw bytes.
inline void PrintTo(const SimTime& t, std::ostream* os) { *os << t.str() << " s"; }

}  // namespace sbsim::kernel
