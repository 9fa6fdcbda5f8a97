#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace sbsim::app {

/// Bad command-line input; the program prints the message and exits with code 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct CommandLine {
    std::optional<std::filesystem::path> sumocfg;  ///< none: the bundled default scenario
    std::optional<std::filesystem::path> story;
    std::optional<std::filesystem::path> events;
    std::optional<double> end;  ///< seconds
    std::optional<std::int64_t> seed;
    std::vector<std::string> sumoOptions;           ///< already split into words
    std::optional<std::filesystem::path> services;  ///< Artery-format services file
    std::vector<std::filesystem::path> plugins;     ///< service-module libraries to load
    double middlewareInterval = 0.1;                ///< s between service triggers
    double v2xRange = 500;                          ///< m
    double v2xLatency = 0.001;                      ///< s
    std::optional<double> v2xFadeStart;             ///< m; none: no packet errors
    bool quiet = false;
    bool help = false;
    bool version = false;
    unsigned threads = 0;     ///< threads reading the per-step snapshot; 0 = all cores
    bool noSnapshot = false;  ///< step SUMO only (a benchmark baseline)

    /// Parses argv (without the program name). Throws UsageError naming the problem.
    static CommandLine parse(const std::vector<std::string>& args);
    static std::string usage();
};

}  // namespace sbsim::app
