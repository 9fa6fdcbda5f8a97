#include "sbsim/app/inputs/OpenScenarioImport.h"

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/run/Interruption.h"

extern char** environ;

namespace sbsim::app {

namespace fs = std::filesystem;

namespace {

/// The Python the importer runs in: the virtual environment's own when sbsim is installed in one
/// (beside the program), else the one sbsim was built with; a source build's `python/` goes on
/// its PYTHONPATH, after any given.
struct ImporterPython {
    fs::path executable;
    std::optional<std::string> pythonPath;
};

ImporterPython importerPython() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path bin = self.parent_path();
        if (fs::exists(bin.parent_path() / "pyvenv.cfg") && fs::exists(bin / "python3")) return {bin / "python3", {}};
    }
    const fs::path sources = fs::path(SBSIM_SOURCE_DIR) / "python";
    const char* given = std::getenv("PYTHONPATH");
    std::string path =
        (given != nullptr && *given != '\0') ? std::string(given) + ":" + sources.string() : sources.string();
    return {fs::path(SBSIM_PYTHON_EXECUTABLE), path};
}

/// Runs `argv` and returns what it wrote on stdout (stderr stays the program's: the importer's notes).
std::string runCapturing(const std::vector<std::string>& argv, const std::optional<std::string>& pythonPath) {
    int pipefd[2];
    if (pipe(pipefd) != 0) throw std::runtime_error(fmt::format("--scenario: pipe: {}", std::strerror(errno)));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipefd[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, pipefd[0]);
    posix_spawn_file_actions_addclose(&actions, pipefd[1]);
    std::vector<std::string> env;
    for (char** e = environ; *e != nullptr; ++e) {
        if (pythonPath && std::strncmp(*e, "PYTHONPATH=", 11) == 0) continue;
        env.emplace_back(*e);
    }
    if (pythonPath) env.push_back("PYTHONPATH=" + *pythonPath);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    std::vector<char*> envp;
    for (std::string& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    close(pipefd[1]);
    if (rc != 0) {
        close(pipefd[0]);
        throw InputError(fmt::format("--scenario: cannot start {}: {}", argv[0], std::strerror(rc)));
    }
    std::string out;
    char buffer[4096];
    for (;;) {
        const ssize_t n = read(pipefd[0], buffer, sizeof buffer);
        if (n > 0) {
            out.append(buffer, static_cast<std::size_t>(n));
        } else if (n == 0 || errno != EINTR) {
            break;
        }
    }
    close(pipefd[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    Interruption::checkpoint("while the scenario was imported");  // Ctrl-C reached the importer too
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        throw InputError(
            fmt::format("--scenario: the OpenSCENARIO importer ({} -m storyboard.openscenario) failed", argv[0]));
    }
    return out;
}

}  // namespace

void importOpenScenario(CommandLine& options) {
    const ImporterPython python = importerPython();
    std::vector<std::string> argv{python.executable.string(), "-m", "storyboard.openscenario", "prepare", "--scenario",
                                  options.scenario->string()};
    if (options.sumocfg) argv.insert(argv.end(), {"--sumocfg", options.sumocfg->string()});
    for (const std::string& p : options.params) argv.insert(argv.end(), {"--param", p});
    for (const std::string& b : options.binds) argv.insert(argv.end(), {"--bind", b});
    const std::string out = runCapturing(argv, python.pythonPath);
    nlohmann::json result;
    try {
        result = nlohmann::json::parse(out);
    } catch (const nlohmann::json::exception&) {
        throw InputError(fmt::format("--scenario: the importer's answer is not JSON: {}", out.substr(0, 200)));
    }
    if (result.contains("error")) throw InputError(result["error"].get<std::string>());
    options.sumocfg = fs::path(result["sumocfg"].get<std::string>());
    options.story = fs::path(result["story"].get<std::string>());
    for (const auto& w : result["sumo_options"]) options.sumoOptions.push_back(w.get<std::string>());
}

}  // namespace sbsim::app
