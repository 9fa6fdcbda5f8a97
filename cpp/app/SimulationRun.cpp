#include "sbsim/app/SimulationRun.h"

#include <fmt/format.h>
#include <libsumo/TraCIDefs.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>

#include "sbsim/app/BadInput.h"
#include "sbsim/app/BundledScenario.h"
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
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/python/PythonRuntime.h"
#include "sbsim/storyboard/python/StoryScript.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::app {

namespace fs = std::filesystem;

namespace {

void requireReadableFile(const std::string& option, const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw InputError(fmt::format("{}: no such file '{}'", option, path.string()));
    if (fs::is_directory(path, ec)) {
        throw InputError(fmt::format("{}: '{}' is a directory, not a file", option, path.string()));
    }
    if (std::ifstream(path).fail()) throw InputError(fmt::format("{}: cannot read '{}'", option, path.string()));
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
            throw InputError(fmt::format("--plugin: cannot load '{}': {}", plugin.string(), e.what()));
        }
        if (const auto name = services::ServiceRegistry::instance().takeConflict()) {
            throw InputError(fmt::format("--plugin: '{}' registers service type '{}', which is already registered",
                                         plugin.string(), *name));
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
        throw InputError(fmt::format("--services: {}", e.what()));
    }
    const services::ServiceRegistry& registry = services::ServiceRegistry::instance();
    for (const services::ServiceSpec& spec : config->services()) {
        if (registry.contains(spec.type)) continue;
        throw InputError(fmt::format("--services: {}:{}: unknown service type '{}' (known: {})", path.string(),
                                     spec.line, spec.type, fmt::join(registry.names(), ", ")));
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
    fmt::print("sbsim {}: {}\n", SBSIM_VERSION, f.sumocfg.filename().string());
    fmt::print("end: {} s ({})\n", f.sim.now().str(),
               Interruption::requested() ? "interrupted" : endReasonText(f.sumo.endReason()));
    fmt::print("steps: {}\n", f.sumo.steps());
    fmt::print("vehicles seen: {}\n", f.sumo.vehiclesSeen());
    fmt::print("peak running: {}\n", f.sumo.peakRunning());
    if (f.board != nullptr) {
        for (const auto& story : f.board->stories()) {
            fmt::print("activations {}: {}\n", story->name(), story->activations());
        }
    }
    if (f.services != nullptr) {
        fmt::print("services created: {}\n", f.services->servicesCreated());
        for (const auto& [type, counts] : f.medium->counts()) {
            fmt::print("messages {}: sent {}, delivered {}\n", type, counts.sent, counts.delivered);
        }
    }
    const double simulated = (f.sim.now() - f.sumo.beginTime()).seconds();
    fmt::print("wall time: {:.3f} s\n", f.wall);
    fmt::print("time in sumo: {:.3f} s\n", f.sumo.sumoSeconds());
    fmt::print("time reading vehicles: {:.3f} s\n", f.sumo.snapshotSeconds());
    if (f.board != nullptr) fmt::print("time in storyboard: {:.3f} s\n", f.board->updateSeconds());
    fmt::print("real-time factor: {:.1f}\n", f.wall > 0 ? simulated / f.wall : 0.0);
}

}  // namespace

int runSimulation(const CommandLine& cl) {
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
        if (!events) throw InputError(fmt::format("--events: cannot write '{}'", cl.events->string()));
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

    kernel::Simulation sim(static_cast<std::uint64_t>(cl.seed.value_or(CommandLine::kDefaultSeed)), cl.threads);
    auto& sumo = sim.emplaceModule<traffic::SumoBridge>(settings);
    try {
        sumo.load();
    } catch (const traffic::SumoLoadError& e) {
        throw InputError(fmt::format("SUMO cannot load '{}': {}", sumocfg.string(), e.what()));
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
            fmt::print(stderr, "sbsim: warning: {} registered no story\n", story->string());
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
        throw std::runtime_error(fmt::format("SUMO error at t={} s: {}", sim.now().str(), e.what()));
    } catch (const services::ServicesConfigError& e) {
        // A service reads its parameters when its first vehicle departs: still bad input.
        throw InputError(fmt::format("--services: {}", e.what()));
    }
    sim.finish();
    if (progress) progress->clear();

    if (!cl.quiet) {
        printSummary(RunFigures{sumocfg, sim, sumo, board, serviceManager, medium,
                                std::chrono::duration<double>(Clock::now() - started).count()});
    }
    if (Interruption::requested()) {
        fmt::print(stderr, "sbsim: interrupted at t={} s\n", sim.now().str());
        return 130;  // the shell's convention for SIGINT
    }
    return 0;
}

}  // namespace sbsim::app
