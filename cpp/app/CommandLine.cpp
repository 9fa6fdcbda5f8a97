#include "sbsim/app/CommandLine.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "sbsim/app/ShellWords.h"

namespace sbsim::app {

namespace {

template <typename T>
T parseNumber(const std::string& option, const std::string& text) {
    T value{};
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end) throw UsageError("option " + option + " expects a number, got '" + text + "'");
    return value;
}

double positive(const std::string& option, double value) {
    if (!std::isfinite(value) || value <= 0) throw UsageError("option " + option + " expects a number > 0");
    return value;
}

/// Times must fit sbsim's clock: whole nanoseconds, at most about a century.
constexpr double kMaxSeconds = 3.0e9;
double duration(const std::string& option, double seconds, bool allowZero) {
    if (!std::isfinite(seconds) || seconds < 0 || (!allowZero && seconds < 1e-9) || seconds > kMaxSeconds) {
        throw UsageError("option " + option + " expects seconds " + (allowZero ? ">= 0" : "> 0 (at least 1e-9)") +
                         " and at most 3e9");
    }
    return seconds;
}

}  // namespace

std::string CommandLine::usage() {
    return R"(usage: sbsim [--sumocfg FILE] [--story FILE.py] [--events FILE.jsonl] [--end SECONDS]
             [--seed N] [--sumo-option "..."]... [--services FILE.xml] [--plugin LIB.so]...
             [--quiet] [--version] [--help]

Runs SUMO through libsumo, with an Artery-style storyboard making traffic dynamic.
Without --sumocfg, runs the bundled scenario (stories/grid-rain).

  --sumocfg FILE       SUMO configuration to load
  --story FILE.py      storyboard script defining createStories(board)
  --events FILE.jsonl  write storyboard events as JSON Lines
  --end SECONDS        stop after the step reaching this time (default: the sumocfg's end)
  --seed N             seed for SUMO (--seed) and the storyboard's random generators
  --sumo-option "..."  extra SUMO options, split into words as a shell would; repeatable
  --services FILE.xml  per-vehicle services (Artery's services file format)
  --plugin LIB.so      load service modules built with sbsim_add_service_module; repeatable
  --middleware-interval SECONDS
                       time between service triggers (default 0.1)
  --v2x-range METRES   broadcast range (default 500)
  --v2x-latency SECONDS
                       broadcast latency (default 0.001)
  --v2x-fade-start METRES
                       packet errors: reception certain up to here, falling linearly to 0 at
                       the range (default: no packet errors)
  --threads N          threads reading vehicle states after each step (default 0: all cores)
  --no-snapshot        only step SUMO, reading no vehicle states (a baseline for benchmarks;
                       not with --story or --services)
  --quiet              no progress, no summary, no SUMO warnings
  --version            print the version and exit
  --help               print this help and exit
)";
}

CommandLine CommandLine::parse(const std::vector<std::string>& args) {
    CommandLine cl;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string option = args[i];
        std::optional<std::string> inlineValue;
        if (const auto eq = option.find('='); option.rfind("--", 0) == 0 && eq != std::string::npos) {
            inlineValue = option.substr(eq + 1);
            option.resize(eq);
        }
        const auto value = [&]() -> std::string {
            if (inlineValue) return *inlineValue;
            if (i + 1 >= args.size()) throw UsageError("option " + option + " needs a value");
            return args[++i];
        };
        const auto flag = [&] {
            if (inlineValue) throw UsageError("option " + option + " takes no value");
            return true;
        };
        if (option == "--sumocfg" || option == "-c") {
            cl.sumocfg = value();
        } else if (option == "--story") {
            cl.story = value();
        } else if (option == "--events") {
            cl.events = value();
        } else if (option == "--end") {
            cl.end = duration(option, parseNumber<double>(option, value()), true);
        } else if (option == "--seed") {
            cl.seed = parseNumber<std::int64_t>(option, value());
        } else if (option == "--sumo-option") {
            const std::string text = value();
            try {
                for (std::string& w : splitShellWords(text)) cl.sumoOptions.push_back(std::move(w));
            } catch (const std::invalid_argument& e) {
                throw UsageError(std::string("option --sumo-option: ") + e.what());
            }
        } else if (option == "--services") {
            cl.services = value();
        } else if (option == "--plugin") {
            cl.plugins.emplace_back(value());
        } else if (option == "--middleware-interval") {
            cl.middlewareInterval = duration(option, parseNumber<double>(option, value()), false);
        } else if (option == "--v2x-range") {
            cl.v2xRange = positive(option, parseNumber<double>(option, value()));
        } else if (option == "--v2x-latency") {
            cl.v2xLatency = duration(option, parseNumber<double>(option, value()), true);
        } else if (option == "--v2x-fade-start") {
            cl.v2xFadeStart = parseNumber<double>(option, value());
            if (!std::isfinite(*cl.v2xFadeStart) || *cl.v2xFadeStart < 0)
                throw UsageError("option --v2x-fade-start expects metres >= 0");
        } else if (option == "--threads") {
            const auto threads = parseNumber<std::int64_t>(option, value());
            if (threads < 0 || threads > 256) throw UsageError("option --threads expects 0 (all cores) to 256");
            cl.threads = static_cast<unsigned>(threads);
        } else if (option == "--no-snapshot") {
            cl.noSnapshot = flag();
        } else if (option == "--quiet" || option == "-q") {
            cl.quiet = flag();
        } else if (option == "--help" || option == "-h") {
            cl.help = flag();
        } else if (option == "--version") {
            cl.version = flag();
        } else if (option.rfind("-", 0) == 0) {
            throw UsageError("unknown option '" + option + "' (see sbsim --help)");
        } else {
            throw UsageError("unexpected argument '" + option + "' (see sbsim --help)");
        }
    }
    if (cl.noSnapshot && (cl.story || cl.services)) {
        throw UsageError("option --no-snapshot cannot be combined with --story or --services: they read the snapshot");
    }
    if (cl.v2xFadeStart && *cl.v2xFadeStart > cl.v2xRange) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "option --v2x-fade-start: the fade start (%g m) must not exceed --v2x-range (%g m)",
                      *cl.v2xFadeStart, cl.v2xRange);
        throw UsageError(text);
    }
    return cl;
}

}  // namespace sbsim::app
