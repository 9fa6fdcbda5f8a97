#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace sbsim::app {

class FileLedger;

/// SUMO's options as sbsim sees them before SUMO loads: those the sumocfg sets and the words for
/// SUMO on sbsim's command line, which override the sumocfg's as they do in SUMO. sbsim reads
/// them to check what SUMO would otherwise trip over: input files that are not regular files (a
/// FIFO blocks SUMO), options that make SUMO a TraCI server or print something and exit, and a
/// state to load.
class SumoOptions {
public:
    /// A sumocfg that does not parse is left for SUMO to report.
    SumoOptions(const std::filesystem::path& sumocfg, const std::vector<std::string>& words);

    /// Throws BadInput (one line naming the option and where it was set) for options sbsim
    /// cannot run SUMO with: --remote-port and --num-clients (SUMO would wait for a TraCI client),
    /// --help, --version, --save-configuration, --save-template and --save-schema (SUMO would
    /// print or write something and exit instead of running).
    void rejectUnrunnable() const;
    /// Adds the files SUMO will read (net, routes, additional and weight files, a state) to
    /// `files`, which checks they are regular files where they exist.
    void addInputs(FileLedger& files) const;
    /// The files option `name` lists (comma-separated, relative to the sumocfg's folder when set
    /// there), and where it was set ("the sumocfg 'x'" or "the SUMO options").
    std::vector<std::filesystem::path> files(const std::string& name) const;
    std::string sourceOf(const std::string& name) const;

private:
    struct Setting {
        std::string value;
        bool inSumocfg = false;
    };
    void readSumocfg();
    void readWords(const std::vector<std::string>& words);

    std::filesystem::path sumocfg_;
    std::map<std::string, Setting> settings_;
};

}  // namespace sbsim::app
