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
#include "sbsim/app/ProgressDisplay.h"
#include "sbsim/app/RunInputs.h"
#include "sbsim/app/Summary.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/services/Medium.h"
#include "sbsim/services/ServiceManager.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/storyboard/CanvasFrame.h"
#include "sbsim/storyboard/EventLog.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/python/PythonRuntime.h"
#include "sbsim/storyboard/python/StoryScript.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::app {

namespace fs = std::filesystem;

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
        board->setWarmupEndTime(kernel::SimTime::fromSeconds(cl.warmup));
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
