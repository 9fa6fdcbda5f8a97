#include "sbsim/app/SimulationRun.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <libsumo/TraCIDefs.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <memory>

#include "sbsim/app/AfterEachStep.h"
#include "sbsim/app/BadInput.h"
#include "sbsim/app/BundledScenario.h"
#include "sbsim/app/DenmTrace.h"
#include "sbsim/app/GuiWatch.h"
#include "sbsim/app/Interruption.h"
#include "sbsim/app/OutputFile.h"
#include "sbsim/app/ProgressDisplay.h"
#include "sbsim/app/RunFiles.h"
#include "sbsim/app/RunInputs.h"
#include "sbsim/app/Summary.h"
#include "sbsim/app/SumoOptions.h"
#include "sbsim/app/SumoStateFile.h"
#include "sbsim/facilities/StationRegistry.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/DiscMedium.h"
#include "sbsim/services/ServiceManager.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/storyboard/CanvasFrame.h"
#include "sbsim/storyboard/EventLog.h"
#include "sbsim/storyboard/StoryError.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/conditions/V2xSource.h"
#include "sbsim/storyboard/python/PythonRuntime.h"
#include "sbsim/storyboard/python/StoryScript.h"
#include "sbsim/traffic/Penetration.h"
#include "sbsim/traffic/SumoBridge.h"
#include "sbsim/traffic/VehicleRegistry.h"

namespace sbsim::app {

namespace fs = std::filesystem;

namespace {

/// Runs one phase of the run. A story error while an interruption is pending is the story's
/// Python code getting KeyboardInterrupt: the phase ends there, as the interruption asked.
template <typename F>
void untilInterrupted(F phase) {
    try {
        phase();
    } catch (const storyboard::StoryError&) {
        if (!Interruption::requested()) throw;
    }
}

}  // namespace

/// SUMO warnings of one kind shown on stderr before they are only counted (--verbose: all).
constexpr std::size_t kWarningsShown = 3;

int runSimulation(const CommandLine& cl) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point started = Clock::now();

    const auto [sumocfg, story] = scenarioFiles(cl, !cl.noSnapshot);
    RunFiles files;
    checkSumoInputs(sumocfg, cl.sumoOptions, files);
    if (story) files.requireInput("--story", *story);
    // Plugins first: their services must be registered before the services file is checked.
    const std::vector<std::unique_ptr<PluginLibrary>> plugins = loadPlugins(cl.plugins, files);
    std::optional<services::ServicesConfig> servicesConfig;
    if (cl.services) servicesConfig = loadServicesConfig(*cl.services, files);
    // Opened once every input is known, so it can be none of them; before SUMO loads, so a path
    // it cannot write fails at once.
    std::optional<OutputFile> events;
    if (cl.events) events.emplace("--events", *cl.events, files);
    std::optional<OutputFile> denmFile;
    if (cl.denmTrace) denmFile.emplace("--denm-trace", *cl.denmTrace, files);
    std::optional<OutputFile> summary;
    if (cl.summary) summary.emplace("--summary", *cl.summary, files);
    std::optional<OutputFile> sumoLog;
    if (cl.sumoLog) sumoLog.emplace("--sumo-log", *cl.sumoLog, files);
    std::optional<GuiWatch> gui;
    if (cl.gui) {
        GuiWatch::requireDisplay();
        gui.emplace(cl.guiScreenshots, files);
    }
    Interruption::checkpoint("before SUMO loaded");

    traffic::SumoSettings settings;
    settings.sumocfg = sumocfg;
    settings.extraOptions = cl.sumoOptions;
    settings.seed = cl.seed;
    if (cl.end) settings.end = kernel::SimTime::fromSeconds(*cl.end);
    settings.quiet = cl.quiet;
    settings.warningsShown = cl.verbose ? SIZE_MAX : kWarningsShown;
    settings.readVehicles = !cl.noSnapshot;
    settings.gui = cl.gui;
    if (cl.gui) settings.beforeClose = &GuiWatch::wakeBeforeClose;
    if (cl.guiDelay)
        settings.extraOptions.insert(settings.extraOptions.end(), {"--delay", fmt::format("{:g}", *cl.guiDelay)});

    // Declared before the simulation so it outlives the stories' Python objects.
    std::optional<storyboard::PythonRuntime> python;
    if (story) python.emplace();

    // One controller and effect stack per vehicle for the stories and the services alike; declared
    // before the simulation, whose modules hold its entries.
    traffic::VehicleRegistry vehicles;
    kernel::Simulation sim(static_cast<std::uint64_t>(cl.seed.value_or(CommandLine::kDefaultSeed)), cl.threads);
    for (const std::string& param : cl.params) {
        try {
            sim.parameters().add(param);
        } catch (const kernel::StudyParameterError& e) {
            throw UsageError(fmt::format("--param: {}", e.what()));
        }
    }
    // The parameters that set options (CommandLine::complete applied them) count as read.
    for (const auto& [name, option] : CommandLine::optionParameters()) (void)sim.parameters().get(name);
    const traffic::Penetration penetration(cl.penetration, sim.seed());
    auto& sumo = sim.emplaceModule<traffic::SumoBridge>(settings);
    if (sumoLog) sumo.warnings().setLog(&sumoLog->stream());
    vehicles.attach(sumo);
    try {
        sumo.load();
    } catch (const traffic::SumoLoadError& e) {
        throw InputError(fmt::format("SUMO cannot load '{}': {}", sumocfg.string(), e.what()));
    }
    Interruption::checkpoint("while SUMO was loading");
    if (settings.end && *settings.end < sumo.beginTime()) {
        throw UsageError(
            fmt::format("--end: {} s is before SUMO's begin time ({} s)", settings.end->str(), sumo.beginTime().str()));
    }

    std::optional<storyboard::EventLog> log;
    if (events) log.emplace(events->stream());
    // What every station heard (LDM, DENM memory): written by the services, read by the stories'
    // V2X conditions, which take it when the script creates them.
    const auto stations = std::make_shared<facilities::StationRegistry>();
    std::optional<DenmTrace> denmTrace;
    if (denmFile) {
        denmTrace.emplace(denmFile->stream());
        stations->setPhaseSink(&*denmTrace);
    }
    storyboard::V2xSource::use(stations);
    storyboard::Storyboard* board = nullptr;
    std::unique_ptr<storyboard::StoryScript> script;
    if (story) {
        board = &sim.emplaceModule<storyboard::Storyboard>(log ? &*log : nullptr);
        board->useRegistry(vehicles);
        board->attach(sumo);
        board->setWarmupEndTime(kernel::SimTime::fromSeconds(cl.warmup));
        if (cl.storyboardEquippedOnly) board->seeEquippedOnly(penetration);
        script = std::make_unique<storyboard::StoryScript>(*python, *story, *board,
                                                           storyboard::CanvasFrame(sumo.netBoundary()));
        std::size_t created = 0;
        untilInterrupted([&] { created = script->createStories(); });
        Interruption::reassert();  // the script may have set handlers of its own
        Interruption::checkpoint("while the story was being created");
        if (created == 0) fmt::print(stderr, "sbsim: warning: {} registered no story\n", story->string());
    }
    if (gui) {
        if (board != nullptr) {
            board->paintStories();
            gui->drawAreas(board->stories());
        }
        sim.subscribe(traffic::SumoBridge::stepSignal, *gui);
    }

    services::ServiceManager* serviceManager = nullptr;
    radio::Medium* medium = nullptr;
    if (servicesConfig) {
        serviceManager = &sim.emplaceModule<services::ServiceManager>(
            std::move(*servicesConfig), kernel::SimTime::fromSeconds(cl.middlewareInterval), sumo.snapshot());
        radio::DiscSettings disc;
        disc.range = cl.v2xRange;
        disc.latency = kernel::SimTime::fromSeconds(cl.v2xLatency);
        disc.fadeStart = cl.v2xFadeStart;
        medium = &sim.emplaceModule<radio::DiscMedium>(disc, sumo.snapshot(), [serviceManager](const std::string& id) {
            return serviceManager->middlewareOf(id);
        });
        serviceManager->useRegistry(vehicles);
        serviceManager->useStations(stations);
        serviceManager->setMedium(*medium);
        serviceManager->setPenetration(penetration);
        serviceManager->attach(sumo);
    }

    std::unique_ptr<ProgressDisplay> progress;
    if (!cl.quiet && isatty(STDERR_FILENO)) {
        progress = std::make_unique<ProgressDisplay>(stderr, sumo.endTime());
        sim.subscribe(traffic::SumoBridge::stepSignal, *progress);
    }
    AfterEachStep checks([&] {
        Interruption::reassert();
        if (Interruption::requested()) sim.stop();
        if (events) events->check();  // a full disk ends the run now, not at its end
    });
    sim.subscribe(traffic::SumoBridge::stepSignal, checks);
    try {
        untilInterrupted([&] { sim.run(); });
        untilInterrupted([&] { sim.finish(); });
    } catch (const traffic::SumoError& e) {
        throw InputError(fmt::format("SUMO error in '{}' at t={} s: {}", sumocfg.string(), sim.now().str(), e.what()));
    } catch (const libsumo::TraCIException& e) {
        throw InputError(fmt::format("SUMO error at t={} s: {}", sim.now().str(), e.what()));
    } catch (const services::ServicesConfigError& e) {
        // A service reads its parameters when its first vehicle departs: still bad input.
        throw InputError(fmt::format("--services: {}", e.what()));
    }
    if (progress) progress->clear();
    if (gui && !Interruption::requested()) gui->finish(sim.now());
    // Only a run that ended as it should gives outputs their names; others stay .incomplete.
    if (events && !Interruption::requested()) events->commit();
    if (sumoLog && !Interruption::requested()) sumoLog->commit();
    if (denmFile && !Interruption::requested()) denmFile->commit();

    const RunFigures figures{sumocfg,
                             sim,
                             sumo,
                             board,
                             serviceManager,
                             medium,
                             std::chrono::duration<double>(Clock::now() - started).count(),
                             cl.arguments};
    if (summary) {
        summary->stream() << summaryJson(figures).dump(2) << '\n';
        if (!Interruption::requested()) summary->commit();
    }
    if (!cl.quiet) {
        printSummary(figures);
        std::fflush(stdout);
    }
    if (python) {
        const std::vector<std::string> lingering =
            python->abandonLingeringThreads(storyboard::PythonRuntime::kThreadGrace);
        if (!lingering.empty()) {
            fmt::print(stderr, "sbsim: warning: the story left threads running ({}); sbsim exits without them\n",
                       fmt::join(lingering, ", "));
        }
    }
    // Only after a whole run: a story may read a parameter late, or only in some branch.
    for (const std::string& name : sim.parameters().unread()) {
        if (Interruption::requested()) break;
        fmt::print(stderr, "sbsim: warning: --param {} was never read by the story or a service\n", name);
    }
    const int exitCode = Interruption::requested() ? 130 : 0;  // 130: the shell's convention for SIGINT
    if (Interruption::requested()) fmt::print(stderr, "sbsim: interrupted at t={} s\n", sim.now().str());
    if (gui) GuiWatch::closeWithin(sumo, std::chrono::seconds(10), exitCode);
    return exitCode;
}

}  // namespace sbsim::app
