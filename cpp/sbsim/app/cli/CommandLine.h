#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace sbsim::app {

/// A sumo-gui screenshot to take (--gui-screenshot SECONDS:FILE).
struct GuiScreenshot {
    double seconds = 0;
    std::filesystem::path file;
};

/// The options of a run: those of `sbsim [options]`, also accepted after a subcommand's name.
struct CommandLine {
    /// SUMO's own default seed; the storyboard's when --seed is not given.
    static constexpr std::int64_t kDefaultSeed = 23423;

    std::optional<std::filesystem::path> sumocfg;  ///< none: the bundled default scenario
    std::optional<std::filesystem::path> story;
    std::optional<std::filesystem::path> scenario;  ///< an OpenSCENARIO file, run as stories
    std::vector<std::string> binds;                 ///< ENTITY=VEHICLE: a SUMO vehicle plays the entity
    std::optional<std::filesystem::path> events;
    std::optional<std::filesystem::path> summary;     ///< the summary as JSON
    std::optional<std::filesystem::path> statistics;  ///< what services and stories recorded, as Parquet
    std::optional<std::filesystem::path> junit;       ///< the criteria's verdicts as JUnit XML
    std::vector<std::string> arguments;               ///< the command line as given (for the JSON summary)
    std::optional<double> end;                        ///< seconds
    std::optional<std::int64_t> seed;
    double warmup = 0;                              ///< s; what board.getWarmupEndTime() returns
    std::vector<std::string> sumoOptions;           ///< words for SUMO: --sumo-option's, then those after `--`
    std::optional<std::filesystem::path> services;  ///< Artery-format services file
    std::vector<std::filesystem::path> plugins;     ///< service-module libraries to load
    std::vector<std::string> params;                ///< study parameters, NAME=VALUE
    double middlewareInterval = 0.1;                ///< s between service triggers
    bool middlewareIntervalGiven = false;           ///< by --middleware-interval or --param (not the default)
    double v2xRange = 500;                          ///< m
    double v2xLatency = 0.001;                      ///< s
    std::optional<double> v2xFadeStart;             ///< m; none: no packet errors
    bool gnForwarding = true;                       ///< GeoNetworking forwards geo-broadcasts (CBF, greedy)
    unsigned gnHopLimit = 10;                       ///< a geo-broadcast's hop limit
    double penetration = 1.0;                       ///< share of vehicles with V2X equipment
    std::optional<std::filesystem::path> radio;     ///< 802.11p channel model settings (TOML); none: the disc
    std::optional<std::filesystem::path> messages;  ///< the message trace (JSON Lines; Parquet for *.parquet)
    std::optional<double> messagesRange;            ///< m; lost lines only this close to the sender
    std::vector<std::string> messagesTypes;         ///< message types the trace keeps; none: all
    std::vector<std::string> messagesEvents;        ///< events the trace keeps; none given: the default
    /// Bytes the trace may take; then it stops (the run goes on). UINT64_MAX: no limit.
    std::uint64_t messagesMaxBytes = kDefaultMessagesMaxBytes;
    static constexpr std::uint64_t kDefaultMessagesMaxBytes = 2'000'000'000;
    bool storyboardEquippedOnly = false;           ///< stories see only equipped vehicles
    std::optional<std::filesystem::path> sumoLog;  ///< every SUMO warning, as SUMO printed it
    bool verbose = false;                          ///< every SUMO warning on stderr, not the first few of a kind
    bool quiet = false;
    unsigned threads = 0;                       ///< threads reading the per-step snapshot; 0 = all cores
    bool noSnapshot = false;                    ///< step SUMO only (a benchmark baseline)
    bool gui = false;                           ///< run inside sumo-gui, showing the stories
    std::optional<double> guiDelay;             ///< ms between steps in sumo-gui (its --delay)
    std::vector<GuiScreenshot> guiScreenshots;  ///< in the order given

    /// Declares the options on `app`, bound to this object's fields (which must outlive parsing),
    /// with their checks, help text and defaults.
    void declareOptions(CLI::App& app);
    /// After parsing: appends `sumoArgs` (the words after `--`) to the SUMO words, taking SUMO's
    /// `-c FILE` from them as the sumocfg, and checks what single options cannot. Throws UsageError.
    void complete(std::vector<std::string> sumoArgs);

    /// Whether the message trace keeps lost receptions: asked for by --messages-events, or by
    /// --messages-range alone (which says how far), as before lost lines became optional.
    bool messagesLost() const;
    /// --messages names a Parquet file (*.parquet).
    bool messagesParquet() const;

    /// Study parameters that set an option of the same name (`--param v2x_range=300` is
    /// `--v2x-range 300`), so that a study can sweep them: name -> option.
    static const std::map<std::string, std::string, std::less<>>& optionParameters();

private:
    void applyOptionParameters();

    std::map<std::string, CLI::Option*, std::less<>> optionsByParameter_;
};

}  // namespace sbsim::app
