#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace sbsim::services::python {

/// The active Python exception in one line, "FILE:LINE: Type: message (during)", at the innermost
/// frame in `file` (the service class's source), else the innermost frame; its traceback goes to
/// stderr first, as a story's does. Clears the exception.
std::string describePythonError(pybind11::error_already_set& error, const std::string& file, const std::string& during);

}  // namespace sbsim::services::python
