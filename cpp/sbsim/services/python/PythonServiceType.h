#pragma once

#include "sbsim/kernel/Export.h"
#include "sbsim/services/ServicesConfig.h"

namespace sbsim::services::python {

/// The prefix of the services file's Python service types: `python:FILE.py:Class` (a file relative
/// to the services file) or `python:package.module:Class` (a module on Python's path: the story's
/// folder, then the services file's).
inline constexpr const char* kPythonPrefix = "python:";

/// Whether `config` names a Python service (on a vehicle or a roadside unit): the run then starts the
/// interpreter before the services.
SBSIM_API bool usesPython(const ServicesConfig& config);

}  // namespace sbsim::services::python
