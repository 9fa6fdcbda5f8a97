#include "sbsim/app/cli/CommandLine.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <functional>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/inputs/SumoWords.h"
#include "sbsim/app/outputs/MessageTraceFilter.h"
#include "sbsim/kernel/StudyParameters.h"

namespace sbsim::app {

namespace {

/// Accepts a number written in full (nothing after it) for which `accept` holds; otherwise the
/// message names what the option expects and the text given (CLI11 prefixes the option).
template <typename T>
CLI::Validator numberWhere(std::string expected, std::function<bool(T)> accept) {
    return CLI::Validator(
        [expected = std::move(expected), accept = std::move(accept)](std::string& text) -> std::string {
            T value{};
            const char* end = text.data() + text.size();
            const auto [ptr, ec] = std::from_chars(text.data(), end, value);
            if (ec == std::errc() && ptr == end && accept(value)) return {};
            return fmt::format("expects {}, got '{}'", expected, text);
        },
        "");  // no description: --help shows the type name and the option's own text
}

/// Times must fit sbsim's clock: whole nanoseconds, at most about a century.
constexpr double kMaxSeconds = 3.0e9;

CLI::Validator seconds(bool allowZero) {
    if (allowZero) {
        return numberWhere<double>("seconds >= 0 and at most 3e9",
                                   [](double s) { return std::isfinite(s) && s >= 0 && s <= kMaxSeconds; });
    }
    // At least 1 ms: a shorter interval makes a few seconds of traffic take minutes.
    return numberWhere<double>("seconds > 0, at least 0.001 (1 ms) and at most 3e9",
                               [](double s) { return std::isfinite(s) && s >= 1e-3 && s <= kMaxSeconds; });
}

CLI::Validator share() {
    return numberWhere<double>("a share between 0 and 1", [](double x) { return x >= 0 && x <= 1; });
}

CLI::Validator metres(bool allowZero) {
    if (allowZero) return numberWhere<double>("metres >= 0", [](double m) { return std::isfinite(m) && m >= 0; });
    return numberWhere<double>("metres > 0", [](double m) { return std::isfinite(m) && m > 0; });
}

/// SECONDS:FILE, the time as --end takes it and a file name not empty.
std::optional<GuiScreenshot> parseScreenshot(const std::string& text) {
    const auto colon = text.find(':');
    if (colon == std::string::npos || colon + 1 == text.size()) return std::nullopt;
    double t = 0;
    const char* begin = text.data();
    const auto [ptr, ec] = std::from_chars(begin, begin + colon, t);
    if (ec != std::errc() || ptr != begin + colon || !std::isfinite(t) || t < 0 || t > kMaxSeconds) return std::nullopt;
    return GuiScreenshot{t, text.substr(colon + 1)};
}

/// A size in bytes: a whole number with an optional suffix k, M, G or T (powers of 1000, as disks
/// are sold; an optional B after it), or "none" for no limit. At least 1 kB: a smaller trace
/// holds nothing useful.
std::optional<std::uint64_t> parseByteSize(std::string text) {
    if (text == "none") return UINT64_MAX;
    if (!text.empty() && (text.back() == 'B' || text.back() == 'b')) text.pop_back();
    std::uint64_t scale = 1;
    if (!text.empty()) {
        switch (text.back()) {
            case 'k':
            case 'K':
                scale = 1'000;
                break;
            case 'm':
            case 'M':
                scale = 1'000'000;
                break;
            case 'g':
            case 'G':
                scale = 1'000'000'000;
                break;
            case 't':
            case 'T':
                scale = 1'000'000'000'000;
                break;
            default:
                break;
        }
        if (scale != 1) text.pop_back();
    }
    std::uint64_t n = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, n);
    if (text.empty() || ec != std::errc() || ptr != end || n > UINT64_MAX / scale) return std::nullopt;
    if (n * scale < 1000) return std::nullopt;
    return n * scale;
}

}  // namespace

void CommandLine::declareOptions(CLI::App& app) {
    // As most programs do: an option given again overrides (repeatable ones collect instead).
    app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);

    app.option_defaults()->group("Scenario");
    app.add_option("-c,--sumocfg", sumocfg,
                   "SUMO configuration to load (default: the bundled scenario\n"
                   "stories/grid-rain with its story); also -c FILE after --")
        ->type_name("FILE");
    auto* storyOption =
        app.add_option("--story", story, "storyboard script defining createStories(board)")->type_name("FILE.py");
    app.add_option("--scenario", scenario,
                   "an OpenSCENARIO 1.x file run as stories (network: --sumocfg's, or\n"
                   "its OpenDRIVE RoadNetwork converted by netconvert)")
        ->type_name("FILE.xosc")
        ->excludes(storyOption);
    app.add_option("--bind", binds,
                   "with --scenario: the SUMO vehicle VEHICLE plays the scenario's entity\n"
                   "ENTITY (its Init position is where SUMO has it); repeatable")
        ->type_name("ENTITY=VEHICLE")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    app.add_option("--end", end,
                   "stop after the step reaching this time (default: the sumocfg's\n"
                   "end; the run also ends when SUMO expects no more vehicles)")
        ->type_name("SECONDS")
        ->check(seconds(true));
    app.add_option("--seed", seed,
                   fmt::format("seed for SUMO (its --seed) and the storyboard's random\n"
                               "generators (default: {}, SUMO's own; a seed in the sumocfg still\n"
                               "applies to SUMO)",
                               kDefaultSeed))
        ->type_name("N")
        ->check(numberWhere<std::int64_t>("an integer", [](std::int64_t) { return true; }));
    app.add_option("--warmup", warmup,
                   "end of the warm-up period, for scripts that ask\n"
                   "board.getWarmupEndTime() (stories run during it too, as in Artery)")
        ->type_name("SECONDS")
        ->check(seconds(true))
        ->capture_default_str();
    app.add_option("--sumo-option",
                   "extra SUMO options, split into words as a shell would\n"
                   "(quotes, $VARIABLES; no command substitution); repeatable;\n"
                   "words after -- reach SUMO without splitting")
        ->type_name("\"...\"")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->each([this](const std::string& text) {
            for (std::string& word : splitSumoOption(text)) sumoOptions.push_back(std::move(word));
        });

    app.option_defaults()->group("Services and V2X");
    auto* servicesOption =
        app.add_option("--services", services, "per-vehicle C++ services (Artery's services file format)")
            ->type_name("FILE.xml");
    app.add_option("--plugin", plugins, "load service modules built with sbsim_add_service_module;\nrepeatable")
        ->type_name("LIB.so")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->allow_extra_args(false);  // one library per --plugin, so a stray word is not taken for one
    app.add_option("--param", params,
                   "a study parameter NAME=VALUE for the story (board.parameters) and\n"
                   "services (studyParameter); repeatable")
        ->type_name("NAME=VALUE")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->allow_extra_args(false)
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                try {
                    kernel::StudyParameters().add(text);
                    return {};
                } catch (const kernel::StudyParameterError& e) {
                    return e.what();
                }
            },
            ""));
    app.add_option("--middleware-interval", middlewareInterval, "time between service triggers")
        ->type_name("SECONDS")
        ->check(seconds(false))
        ->capture_default_str();
    app.add_option("--v2x-range", v2xRange, "broadcast range")
        ->type_name("METRES")
        ->check(metres(false))
        ->capture_default_str();
    app.add_option("--v2x-latency", v2xLatency, "broadcast latency")
        ->type_name("SECONDS")
        ->check(seconds(true))
        ->capture_default_str();
    app.add_option("--v2x-fade-start", v2xFadeStart,
                   "packet errors: reception certain up to here, falling linearly\n"
                   "to 0 at the range, at most --v2x-range (default: no packet errors)")
        ->type_name("METRES")
        ->check(metres(true));
    app.add_option("--gn-forwarding", gnForwarding,
                   "GeoNetworking forwards geo-broadcasts (DENMs) through their\n"
                   "area (contention-based) and towards it (greedy); off: one hop")
        ->type_name("on|off")
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                for (const char* word : {"on", "off", "true", "false", "1", "0"})
                    if (text == word) return {};
                return fmt::format("expects on or off, got '{}'", text);
            },
            ""))
        ->default_str("on");
    app.add_option("--gn-hop-limit", gnHopLimit, "hops a geo-broadcast may make (its first transmission counts)")
        ->type_name("N")
        ->check(numberWhere<unsigned>("1 to 255", [](unsigned n) { return n >= 1 && n <= 255; }))
        ->capture_default_str();
    app.add_option("--penetration", penetration,
                   "share of vehicles with V2X equipment, drawn per vehicle id from\n"
                   "the seed (the same vehicles in every run with that seed); the\n"
                   "others get only services with <equipped match=\"inverse\"|\"any\"/>")
        ->type_name("SHARE")
        ->check(share())
        ->capture_default_str();
    app.add_option("--radio", radio,
                   "the 802.11p channel model (path loss, shadowing, buildings,\n"
                   "interference, CSMA/CA, DCC) with this settings file, instead\n"
                   "of the --v2x-* disc; study parameters radio_<key> override it")
        ->type_name("FILE.toml");
    auto* messagesOption = app.add_option("--messages", messages,
                                          "write every transmission and reception (and, when asked,\n"
                                          "lost reception) as JSON Lines, or as Parquet for a .parquet")
                               ->type_name("FILE.jsonl");
    app.add_option("--messages-types", messagesTypes,
                   "the trace keeps only these message types, e.g. CAM,DENM\n"
                   "(default: all; denm lines count as DENM)")
        ->type_name("TYPE,...")
        ->delimiter(',')
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->allow_extra_args(false)
        ->needs(messagesOption)
        ->check(CLI::Validator(
            [](std::string& word) -> std::string {
                if (word.empty() || word.find(' ') != std::string::npos)
                    return fmt::format("expects message type names separated by commas, got '{}'", word);
                return {};
            },
            ""));
    app.add_option("--messages-events", messagesEvents,
                   "the trace keeps only these events: tx, rx, lost, denm, dcc\n"
                   "(default: tx,rx,denm,dcc; lost receptions only when named here,\n"
                   "or with --messages-range)")
        ->type_name("EVENT,...")
        ->delimiter(',')
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->allow_extra_args(false)
        ->needs(messagesOption)
        ->check(CLI::Validator(
            [](std::string& word) -> std::string {
                if (MessageTraceFilter::eventNamed(word)) return {};
                return fmt::format("expects events among {}, got '{}'", MessageTraceFilter::eventNames(), word);
            },
            ""));
    app.add_option("--messages-range", messagesRange,
                   "trace lost receptions, for stations this close to the\n"
                   "sender (default: the radio file's trace_range, 500 m;\n"
                   "the disc model: 1000 m)")
        ->type_name("METRES")
        ->check(metres(true));
    app.add_option_function<std::string>(
           "--messages-max-bytes", [this](const std::string& text) { messagesMaxBytes = *parseByteSize(text); },
           "the trace stops (with a warning; the run goes on) before it\n"
           "passes this size: bytes, or with k, M, G, T (powers of 1000);\n"
           "none: no limit (default: 2G)")
        ->type_name("SIZE")
        ->needs(messagesOption)
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                if (parseByteSize(text)) return {};
                return fmt::format("expects a size of at least 1000 bytes such as 500M or 2G (or none), got '{}'",
                                   text);
            },
            ""));
    app.add_flag("--storyboard-equipped-only", storyboardEquippedOnly,
                 "stories see only equipped vehicles, as egos and as others\n"
                 "(as in Artery, where only vehicles with a middleware take part)");
    for (const auto& [name, option] : optionParameters()) optionsByParameter_[name] = app.get_option(option);

    app.option_defaults()->group("Run and output");
    app.add_option("--events", events, "write storyboard events as JSON Lines")->type_name("FILE.jsonl");
    app.add_option("--summary", summary, "also write the summary as one JSON document")->type_name("FILE.json");
    app.add_option("--statistics", statistics,
                   "write what services and stories recorded (vehicle, source,\nname, time, value) as Parquet")
        ->type_name("FILE.parquet");
    app.add_option("--junit", junit, "write the story's criteria as JUnit XML (a test case each)")
        ->type_name("FILE.xml");
    app.add_option("--threads", threads, "threads reading vehicle states after each step (0: all\ncores)")
        ->type_name("N")
        ->check(numberWhere<unsigned>("0 (all cores) to 256", [](unsigned n) { return n <= 256; }))
        ->capture_default_str();
    app.add_flag("--no-snapshot", noSnapshot,
                 "only step SUMO, reading no vehicle states (a baseline for\n"
                 "benchmarks; not with --story or --services: they read them)")
        ->excludes(storyOption)
        ->excludes(servicesOption);
    app.add_option(
           "--sumo-log", sumoLog,
           "write every SUMO warning to this file (stderr shows the\nfirst 3 of each kind; the summary counts them)")
        ->type_name("FILE");
    auto* verboseFlag =
        app.add_flag("-v,--verbose", verbose, "show every SUMO warning on stderr, not the first 3 of a kind");
    app.add_flag("-q,--quiet", quiet, "no progress, no summary, no SUMO warnings")->excludes(verboseFlag);

    app.option_defaults()->group("Watching (sumo-gui)");
    auto* guiFlag = app.add_flag("--gui", gui,
                                 "run inside sumo-gui: story areas drawn, vehicles in their active\n"
                                 "story's colour; needs an X display (xvfb-run without one). SUMO's\n"
                                 "GUI options go through --sumo-option, e.g. \"--start --quit-on-end\"");
    app.add_option("--gui-delay", guiDelay, "wait between steps in sumo-gui (its --delay)")
        ->type_name("MS")
        ->check(numberWhere<double>("milliseconds >= 0 and at most 1e9",
                                    [](double ms) { return std::isfinite(ms) && ms >= 0 && ms <= 1e9; }))
        ->needs(guiFlag);
    app.add_option("--gui-screenshot",
                   "save sumo-gui's view as FILE (PNG, ...) at the first step\n"
                   "reaching SECONDS, at the view's size; repeatable")
        ->type_name("SECONDS:FILE")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->allow_extra_args(false)
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                if (parseScreenshot(text)) return {};
                return fmt::format("expects SECONDS:FILE (seconds >= 0 and at most 3e9), got '{}'", text);
            },
            ""))
        ->each([this](const std::string& text) { guiScreenshots.push_back(*parseScreenshot(text)); })
        ->needs(guiFlag);

    // Options declared later (a subcommand's) start from CLI11's defaults again.
    app.option_defaults()->group("Options")->multi_option_policy(CLI::MultiOptionPolicy::Throw);
}

void CommandLine::complete(std::vector<std::string> sumoArgs) {
    if (const auto file = takeConfigurationFile(sumoArgs)) {
        if (sumocfg) {
            throw UsageError(fmt::format("--sumocfg: given twice: '{}', and '{}' with -c after --", sumocfg->string(),
                                         file->string()));
        }
        sumocfg = *file;
    }
    sumoOptions.insert(sumoOptions.end(), sumoArgs.begin(), sumoArgs.end());
    applyOptionParameters();
    if (const auto it = optionsByParameter_.find("middleware_interval"); it != optionsByParameter_.end())
        middlewareIntervalGiven = it->second->count() > 0;
    if (guiDelay && std::any_of(sumoOptions.begin(), sumoOptions.end(),
                                [](const std::string& w) { return w == "--delay" || w == "-d"; })) {
        throw UsageError("--gui-delay: SUMO's --delay is given too (through --sumo-option or after --); give one");
    }
    if (messagesRange && !messagesEvents.empty() &&
        std::find(messagesEvents.begin(), messagesEvents.end(), "lost") == messagesEvents.end()) {
        throw UsageError(
            "--messages-range: it says how far lost receptions are traced, but --messages-events "
            "leaves out lost");
    }
    if (v2xFadeStart && *v2xFadeStart > v2xRange) {
        throw UsageError(fmt::format("--v2x-fade-start: the fade start ({:g} m) must not exceed --v2x-range ({:g} m)",
                                     *v2xFadeStart, v2xRange));
    }
}

bool CommandLine::messagesLost() const {
    if (messagesEvents.empty()) return messagesRange.has_value();
    return std::find(messagesEvents.begin(), messagesEvents.end(), "lost") != messagesEvents.end();
}

bool CommandLine::messagesParquet() const {
    if (!messages) return false;
    std::string extension = messages->extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".parquet";
}

const std::map<std::string, std::string, std::less<>>& CommandLine::optionParameters() {
    static const std::map<std::string, std::string, std::less<>> names{
        {"gn_forwarding", "--gn-forwarding"},
        {"gn_hop_limit", "--gn-hop-limit"},
        {"middleware_interval", "--middleware-interval"},
        {"penetration", "--penetration"},
        {"v2x_fade_start", "--v2x-fade-start"},
        {"v2x_latency", "--v2x-latency"},
        {"v2x_range", "--v2x-range"},
    };
    return names;
}

void CommandLine::applyOptionParameters() {
    for (const std::string& assignment : params) {
        const auto eq = assignment.find('=');
        const std::string name = assignment.substr(0, eq);
        const auto it = optionsByParameter_.find(name);
        if (it == optionsByParameter_.end()) continue;
        CLI::Option& option = *it->second;
        if (option.count() > 0) {
            throw UsageError(fmt::format("--param {}: {} is given as an option too", assignment, option.get_name()));
        }
        // The option's own conversion and checks, as if it had been given.
        option.add_result(assignment.substr(eq + 1));
        try {
            option.run_callback();
        } catch (const CLI::ParseError& e) {
            throw UsageError(fmt::format("--param {}: {}", assignment, e.what()));
        }
    }
}

}  // namespace sbsim::app
