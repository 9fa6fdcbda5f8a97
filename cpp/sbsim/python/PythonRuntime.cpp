#include "sbsim/python/PythonRuntime.h"

#include <pybind11/embed.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <stdexcept>
#include <string>

namespace py = pybind11;
namespace fs = std::filesystem;

namespace sbsim::python {

namespace {

/// The interpreter Python should consider itself to be: the environment's own python3 when this
/// program was installed into a virtual environment (Python then reads its pyvenv.cfg and uses its
/// site-packages), else the interpreter recorded at build time. sys.executable is then a real
/// Python, so story scripts can start subprocesses with it.
fs::path interpreterIdentity() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path bin = self.parent_path();
        if (fs::exists(bin.parent_path() / "pyvenv.cfg") && fs::exists(bin / "python3")) return bin / "python3";
    }
    return fs::path(SBSIM_PYTHON_EXECUTABLE);
}

void check(PyStatus status, const char* what) {
    if (PyStatus_Exception(status)) {
        throw std::runtime_error(std::string("cannot start the embedded Python (") + what +
                                 "): " + (status.err_msg ? status.err_msg : "unknown error"));
    }
}

/// Whether an interpreter is running, for the signal handler.
std::atomic<bool> running{false};

/// Makes Python's own table say KeyboardInterrupt for SIGINT (PyErr_SetInterrupt then raises it)
/// while the process keeps its own handlers: signal.signal() installs Python's, so they are put
/// back right after.
void routeInterruptsToKeyboardInterrupt() {
    struct sigaction intAction {};
    struct sigaction termAction {};
    sigaction(SIGINT, nullptr, &intAction);
    sigaction(SIGTERM, nullptr, &termAction);
    const py::module_ signal = py::module_::import("signal");
    signal.attr("signal")(SIGINT, signal.attr("default_int_handler"));
    sigaction(SIGINT, &intAction, nullptr);
    sigaction(SIGTERM, &termAction, nullptr);
}

}  // namespace

PythonRuntime::PythonRuntime() {
    PyConfig config;
    PyConfig_InitPythonConfig(&config);
    config.parse_argv = 0;
    // Ctrl-C belongs to sbsim (stop at a safe point, close SUMO); Python only hears of it.
    config.install_signal_handlers = 0;
    const std::string identity = interpreterIdentity().string();
    check(PyConfig_SetBytesString(&config, &config.program_name, identity.c_str()), "program name");
    check(PyConfig_SetBytesString(&config, &config.executable, identity.c_str()), "executable");
    // scoped_interpreter takes over the config (and clears it).
    interpreter_ = std::make_unique<py::scoped_interpreter>(&config, 0, nullptr, false);
    routeInterruptsToKeyboardInterrupt();
    running.store(true);
}

PythonRuntime::~PythonRuntime() {
    if (!threadsChecked_) abandonLingeringThreads(kThreadGrace);
    running.store(false);
    if (!threadsLinger_) return;
    // Finalizing would join the lingering threads: the interpreter is left to the process's end,
    // after what the scripts printed is flushed (finalizing would have done that).
    try {
        const py::module_ sys = py::module_::import("sys");
        for (const char* stream : {"stdout", "stderr"}) {
            if (!sys.attr(stream).is_none()) sys.attr(stream).attr("flush")();
        }
    } catch (const std::exception&) {
        PyErr_Clear();
    }
    // Kept reachable from a global, never destroyed: the process ends without finalizing (that
    // would wait for the thread), and LeakSanitizer sees a live object rather than a leak.
    static const pybind11::scoped_interpreter* volatile abandoned = nullptr;  // volatile: the store stays
    abandoned = interpreter_.release();
}

std::vector<std::string> PythonRuntime::abandonLingeringThreads(std::chrono::milliseconds grace) {
    threadsChecked_ = true;
    std::vector<std::string> names;
    try {
        const py::module_ threading = py::module_::import("threading");
        const py::object mainThread = threading.attr("main_thread")();
        const auto deadline = std::chrono::steady_clock::now() + grace;
        for (const py::handle thread : threading.attr("enumerate")()) {
            if (thread.is(mainThread) || thread.attr("daemon").cast<bool>()) continue;
            const std::chrono::duration<double> left = deadline - std::chrono::steady_clock::now();
            thread.attr("join")(std::max(0.0, left.count()));
            if (thread.attr("is_alive")().cast<bool>()) names.push_back(py::str(thread.attr("name")));
        }
    } catch (const std::exception&) {
        // Interrupted while waiting (KeyboardInterrupt): whatever still runs is abandoned.
        PyErr_Clear();
        threadsLinger_ = true;
        return names;
    }
    threadsLinger_ = !names.empty();
    return names;
}

void PythonRuntime::interruptFromSignalHandler() {
    if (running.load()) PyErr_SetInterruptEx(SIGINT);
}

void PythonRuntime::prependPath(const fs::path& dir) {
    py::module_::import("sys").attr("path").attr("insert")(0, fs::absolute(dir).string());
}

}  // namespace sbsim::python
