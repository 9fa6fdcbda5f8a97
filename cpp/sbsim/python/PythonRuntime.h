#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace pybind11 {
class scoped_interpreter;
}

namespace sbsim::python {

/// The embedded Python interpreter, alive for the object's lifetime. It is configured as the
/// Python sbsim was built for: when the program sits in a virtual environment's bin/ (a pip
/// install), Python finds that environment's pyvenv.cfg and site-packages (numpy, storyboard);
/// otherwise it is pointed at the interpreter recorded at build time.
///
/// Signals stay the program's: Python installs no handler of its own, but
/// interruptFromSignalHandler() makes the code running in Python raise KeyboardInterrupt.
class SBSIM_API PythonRuntime {
public:
    /// How long the destructor waits for threads a script left running (unless
    /// abandonLingeringThreads() was asked already).
    static constexpr std::chrono::milliseconds kThreadGrace{2000};

    PythonRuntime();
    /// Finalizes the interpreter, unless a script's non-daemon thread is still running after
    /// the grace time: finalizing would wait for it forever, so the interpreter is then left
    /// as it is (the process ends without the thread).
    ~PythonRuntime();
    PythonRuntime(const PythonRuntime&) = delete;
    PythonRuntime& operator=(const PythonRuntime&) = delete;

    /// Puts `dir` first on sys.path (the story script's folder).
    void prependPath(const std::filesystem::path& dir);

    /// Waits up to `grace` in all for the non-daemon threads scripts started, and returns the
    /// names of those still running; the destructor then leaves them (and the interpreter) be.
    std::vector<std::string> abandonLingeringThreads(std::chrono::milliseconds grace);

    /// Async-signal-safe: if an interpreter is running, the Python code running now (or next)
    /// raises KeyboardInterrupt.
    static void interruptFromSignalHandler();

private:
    std::unique_ptr<pybind11::scoped_interpreter> interpreter_;
    bool threadsChecked_ = false;
    bool threadsLinger_ = false;
};

}  // namespace sbsim::python
