#pragma once

#include "sbsim/kernel/Export.h"

namespace sbsim::kernel {

/// Polymorphic base for signal payloads (OMNeT++'s cObject role): listeners downcast with
/// dynamic_cast to the type they expect.
class SBSIM_API Object {
public:
    virtual ~Object() = default;
};

}  // namespace sbsim::kernel
