#include "sbsim/storyboard/python/PythonRuntime.h"

#include <pybind11/embed.h>

#include <stdexcept>
#include <string>

namespace py = pybind11;
namespace fs = std::filesystem;

namespace sbsim::storyboard {

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

}  // namespace

PythonRuntime::PythonRuntime() {
    PyConfig config;
    PyConfig_InitPythonConfig(&config);
    config.parse_argv = 0;
    // Ctrl-C belongs to sbsim (stop after the step, close SUMO), not to Python's KeyboardInterrupt.
    config.install_signal_handlers = 0;
    const std::string identity = interpreterIdentity().string();
    check(PyConfig_SetBytesString(&config, &config.program_name, identity.c_str()), "program name");
    check(PyConfig_SetBytesString(&config, &config.executable, identity.c_str()), "executable");
    // scoped_interpreter takes over the config (and clears it).
    interpreter_ = std::make_unique<py::scoped_interpreter>(&config, 0, nullptr, false);
}

PythonRuntime::~PythonRuntime() = default;

void PythonRuntime::prependPath(const fs::path& dir) {
    py::module_::import("sys").attr("path").attr("insert")(0, fs::absolute(dir).string());
}

}  // namespace sbsim::storyboard
