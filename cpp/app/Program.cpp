#include "sbsim/app/Program.h"

#include <libsumo/TraCIDefs.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include "sbsim/app/BundledScenario.h"
#include "sbsim/app/CommandLine.h"
#include "sbsim/app/Interruption.h"
#include "sbsim/app/PluginLibrary.h"
#include "sbsim/app/ProgressDisplay.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/services/Medium.h"
#include "sbsim/services/ServiceManager.h"
#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/storyboard/CanvasFrame.h"
#include "sbsim/storyboard/EventLog.h"
#include "sbsim/storyboard/StoryError.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/python/PythonRuntime.h"
#include "sbsim/storyboard/python/StoryScript.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::app {

namespace fs = std::filesystem;

namespace {

/// SUMO's own default seed, used for the storyboard too when --seed is not given.
constexpr std::int64_t kDefaultSeed = 23423;

/// Bad input found after parsing (unreadable files and the like): exit code 2 as well.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

void requireReadableFile(const std::string& option, const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError(option + ": no such file '" + path.string() + "'");
    if (fs::is_directory(path, ec)) throw InputError(option + ": '" + path.string() + "' is a directory, not a file");
    if (std::ifstream(path).fail()) throw InputError(option + ": cannot read '" + path.string() + "'");
}

const char* endReasonText(traffic::SumoBridge::EndReason r) {
    switch (r) {
        case traffic::SumoBridge::EndReason::EndTime:
            return "end time reached";
        case traffic::SumoBridge::EndReason::NoMoreVehicles:
            return "no more vehicles expected";
        case traffic::SumoBridge::EndReason::Running:
            break;
    }
    return "stopped";
}

std::vector<std::unique_ptr<PluginLibrary>> loadPlugins(const std::vector<fs::path>& paths) {
    std::vector<std::unique_ptr<PluginLibrary>> plugins;
    for (const fs::path& plugin : paths) {
        requireReadableFile("--plugin", plugin);
        try {
            plugins.push_back(std::make_unique<PluginLibrary>(plugin));
        } catch (const std::exception& e) {
            throw InputError("--plugin: cannot load '" + plugin.string() + "': " + e.what());
        }
        if (const auto name = services::ServiceRegistry::instance().takeConflict()) {
            throw InputError("--plugin: '" + plugin.string() + "' registers service type '" + *name +
                             "', which is already registered");
        }
    }
    return plugins;
}

/// The services file, with every service type it names known to the registry.
services::ServicesConfig loadServicesConfig(const fs::path& path) {
    requireReadableFile("--services", path);
    std::optional<services::ServicesConfig> config;
    try {
        config = services::ServicesConfig::load(path);
    } catch (const std::exception& e) {
        throw InputError(std::string("--services: ") + e.what());
    }
    const services::ServiceRegistry& registry = services::ServiceRegistry::instance();
    for (const services::ServiceSpec& spec : config->services()) {
        if (registry.contains(spec.type)) continue;
        std::string known;
        for (const std::string& n : registry.names()) known += (known.empty() ? "" : ", ") + n;
        throw InputError("--services: " + path.string() + ":" + std::to_string(spec.line) + ": unknown service type '" +
                         spec.type + "' (known: " + known + ")");
    }
    return std::move(*config);
}

/// What the final summary reports on.
struct RunFigures {
    const fs::path& sumocfg;
    const kernel::Simulation& sim;
    const traffic::SumoBridge& sumo;
    const storyboard::Storyboard* board;
    const services::ServiceManager* services;
    const services::Medium* medium;
    double wall;  ///< s
};

/// `key: value` lines on stdout: first what the run did (identical for identical runs), then the
/// timing lines.
void printSummary(const RunFigures& f) {
    const auto count = [](std::uint64_t n) { return static_cast<unsigned long long>(n); };
    std::printf("sbsim %s: %s\n", SBSIM_VERSION, f.sumocfg.filename().string().c_str());
    std::printf("end: %s s (%s)\n", f.sim.now().str().c_str(),
                Interruption::requested() ? "interrupted" : endReasonText(f.sumo.endReason()));
    std::printf("steps: %llu\n", count(f.sumo.steps()));
    std::printf("vehicles seen: %llu\n", count(f.sumo.vehiclesSeen()));
    std::printf("peak running: %zu\n", f.sumo.peakRunning());
    if (f.board != nullptr) {
        for (const auto& story : f.board->stories()) {
            std::printf("activations %s: %llu\n", story->name().c_str(), count(story->activations()));
        }
    }
    if (f.services != nullptr) {
        std::printf("services created: %zu\n", f.services->servicesCreated());
        for (const auto& [type, counts] : f.medium->counts()) {
            std::printf("messages %s: sent %llu, delivered %llu\n", type.c_str(), count(counts.sent),
                        count(counts.delivered));
        }
    }
    const double simulated = (f.sim.now() - f.sumo.beginTime()).seconds();
    std::printf("wall time: %.3f s\n", f.wall);
    std::printf("time in sumo: %.3f s\n", f.sumo.sumoSeconds());
    std::printf("time reading vehicles: %.3f s\n", f.sumo.snapshotSeconds());
    if (f.board != nullptr) std::printf("time in storyboard: %.3f s\n", f.board->updateSeconds());
    std::printf("real-time factor: %.1f\n", f.wall > 0 ? simulated / f.wall : 0.0);
}

int run(const CommandLine& cl) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point started = Clock::now();

    fs::path sumocfg;
    std::optional<fs::path> story = cl.story;
    if (cl.sumocfg) {
        sumocfg = *cl.sumocfg;
    } else {
        const BundledScenario bundled = BundledScenario::locate();
        sumocfg = bundled.sumocfg;
        if (!story && !cl.noSnapshot) story = bundled.story;
    }
    requireReadableFile("--sumocfg", sumocfg);
    if (story) requireReadableFile("--story", *story);
    // Plugins first: their services must be registered before the services file is checked.
    const std::vector<std::unique_ptr<PluginLibrary>> plugins = loadPlugins(cl.plugins);
    std::optional<services::ServicesConfig> servicesConfig;
    if (cl.services) servicesConfig = loadServicesConfig(*cl.services);
    std::ofstream events;
    if (cl.events) {
        events.open(*cl.events, std::ios::out | std::ios::trunc);
        if (!events) throw InputError("--events: cannot write '" + cl.events->string() + "'");
    }

    traffic::SumoSettings settings;
    settings.sumocfg = sumocfg;
    settings.extraOptions = cl.sumoOptions;
    settings.seed = cl.seed;
    if (cl.end) settings.end = kernel::SimTime::fromSeconds(*cl.end);
    settings.quiet = cl.quiet;
    settings.readVehicles = !cl.noSnapshot;

    // Declared before the simulation so it outlives the stories' Python objects.
    std::optional<storyboard::PythonRuntime> python;
    if (story) python.emplace();

    kernel::Simulation sim(static_cast<std::uint64_t>(cl.seed.value_or(kDefaultSeed)), cl.threads);
    auto& sumo = sim.emplaceModule<traffic::SumoBridge>(settings);
    try {
        sumo.load();
    } catch (const traffic::SumoLoadError& e) {
        throw InputError("SUMO cannot load '" + sumocfg.string() + "': " + e.what());
    }

    std::optional<storyboard::EventLog> log;
    if (events.is_open()) log.emplace(events);
    storyboard::Storyboard* board = nullptr;
    std::unique_ptr<storyboard::StoryScript> script;
    if (story) {
        board = &sim.emplaceModule<storyboard::Storyboard>(log ? &*log : nullptr);
        board->attach(sumo);
        script = std::make_unique<storyboard::StoryScript>(*python, *story, *board,
                                                           storyboard::CanvasFrame(sumo.netBoundary()));
        if (script->createStories() == 0) {
            std::fprintf(stderr, "sbsim: warning: %s registered no story\n", story->string().c_str());
        }
    }

    services::ServiceManager* serviceManager = nullptr;
    services::Medium* medium = nullptr;
    if (servicesConfig) {
        serviceManager = &sim.emplaceModule<services::ServiceManager>(
            std::move(*servicesConfig), kernel::SimTime::fromSeconds(cl.middlewareInterval), sumo.snapshot());
        services::MediumSettings radio;
        radio.range = cl.v2xRange;
        radio.latency = kernel::SimTime::fromSeconds(cl.v2xLatency);
        radio.fadeStart = cl.v2xFadeStart;
        medium = &sim.emplaceModule<services::Medium>(radio, sumo.snapshot(), [serviceManager](const std::string& id) {
            return serviceManager->middlewareOf(id);
        });
        serviceManager->setMedium(*medium);
        serviceManager->attach(sumo);
    }

    std::unique_ptr<ProgressDisplay> progress;
    if (!cl.quiet && isatty(STDERR_FILENO)) {
        progress = std::make_unique<ProgressDisplay>(stderr, sumo.endTime());
        sim.subscribe(traffic::SumoBridge::stepSignal, *progress);
    }
    Interruption interruption(sim);
    sim.subscribe(traffic::SumoBridge::stepSignal, interruption);
    try {
        sim.run();
    } catch (const libsumo::TraCIException& e) {
        throw std::runtime_error("SUMO error at t=" + sim.now().str() + " s: " + e.what());
    } catch (const services::ServicesConfigError& e) {
        // A service reads its parameters when its first vehicle departs: still bad input.
        throw InputError(std::string("--services: ") + e.what());
    }
    sim.finish();
    if (progress) progress->clear();

    if (!cl.quiet) {
        printSummary(RunFigures{sumocfg, sim, sumo, board, serviceManager, medium,
                                std::chrono::duration<double>(Clock::now() - started).count()});
    }
    if (Interruption::requested()) {
        std::fprintf(stderr, "sbsim: interrupted at t=%s s\n", sim.now().str().c_str());
        return 130;  // the shell's convention for SIGINT
    }
    return 0;
}

}  // namespace

int runProgram(const std::vector<std::string>& args) {
    try {
        const CommandLine cl = CommandLine::parse(args);
        if (cl.help) {
            std::cout << CommandLine::usage();
            return 0;
        }
        if (cl.version) {
            std::cout << "sbsim " << SBSIM_VERSION << "\n";
            return 0;
        }
        return run(cl);
    } catch (const UsageError& e) {
        std::cerr << "sbsim: " << e.what() << "\n";
        return 2;
    } catch (const InputError& e) {
        std::cerr << "sbsim: " << e.what() << "\n";
        return 2;
    } catch (const storyboard::StoryError& e) {
        std::cerr << e.details() << "sbsim: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "sbsim: error: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace sbsim::app
