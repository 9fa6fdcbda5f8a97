#pragma once

#include <stdexcept>

#include "sbsim/kernel/Export.h"

namespace sbsim::services {

/// An exception a service's own code threw, as "service TYPE on vehicle ID at t=T s: what": the
/// user's code, like a story's, so the run ends as bad input (exit 2), not as sbsim's failure.
class SBSIM_API ServiceError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace sbsim::services
