#pragma once

#include <filesystem>
#include <memory>

#include "sbsim/kernel/Export.h"

namespace pybind11 {
class scoped_interpreter;
}

namespace sbsim::storyboard {

/// The embedded Python interpreter, alive for the object's lifetime. It is configured as the
/// Python sbsim was built for: when the program sits in a virtual environment's bin/ (a pip
/// install), Python finds that environment's pyvenv.cfg and site-packages (numpy, storyboard);
/// otherwise it is pointed at the interpreter recorded at build time.
class SBSIM_API PythonRuntime {
public:
    PythonRuntime();
    ~PythonRuntime();
    PythonRuntime(const PythonRuntime&) = delete;
    PythonRuntime& operator=(const PythonRuntime&) = delete;

    /// Puts `dir` first on sys.path (the story script's folder).
    void prependPath(const std::filesystem::path& dir);

private:
    std::unique_ptr<pybind11::scoped_interpreter> interpreter_;
};

}  // namespace sbsim::storyboard
