#include "sbsim/app/run/RunCommand.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <libsumo/TraCIDefs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <memory>
#include <set>
#include <system_error>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/inputs/BundledScenario.h"
#include "sbsim/app/inputs/FileLedger.h"
#include "sbsim/app/inputs/RouteIds.h"
#include "sbsim/app/inputs/ScenarioInputs.h"
#include "sbsim/app/inputs/SumoOptions.h"
#include "sbsim/app/inputs/SumoStateFile.h"
#include "sbsim/app/outputs/JUnitReport.h"
#include "sbsim/app/outputs/JsonLinesTrace.h"
#include "sbsim/app/outputs/MessageTraceFile.h"
#include "sbsim/app/outputs/OutputFile.h"
#include "sbsim/app/outputs/ParquetTrace.h"
#include "sbsim/app/outputs/Summary.h"
#include "sbsim/app/run/AfterEachStep.h"
#include "sbsim/app/run/GuiWatch.h"
#include "sbsim/app/run/Interruption.h"
#include "sbsim/app/run/NetworkQuestions.h"
#include "sbsim/app/run/ProgressDisplay.h"
#include "sbsim/app/run/Scenario.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/services/ServiceError.h"
#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/storyboard/EventLog.h"
#include "sbsim/storyboard/StoryCheck.h"
#include "sbsim/storyboard/StoryError.h"
#include "sbsim/storyboard/StoryPainter.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/python/StoryScript.h"
#include "sbsim/traffic/Penetration.h"
#include "sbsim/traffic/SumoBridge.h"

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
    } catch (const services::ServiceError&) {  // a Python service's KeyboardInterrupt likewise
        if (!Interruption::requested()) throw;
    }
}

/// The trace's lines as --messages-types and --messages-events say (see MessageTraceFilter).
MessageTraceFilter traceFilter(const CommandLine& cl) {
    MessageTraceFilter filter;
    if (!cl.messagesEvents.empty()) {
        std::set<MessageTraceFilter::Event> events;
        for (const std::string& name : cl.messagesEvents) events.insert(*MessageTraceFilter::eventNamed(name));
        filter.setEvents(events);
    } else if (cl.messagesLost()) {
        filter.setEvents({MessageTraceFilter::Event::Tx, MessageTraceFilter::Event::Rx, MessageTraceFilter::Event::Lost,
                          MessageTraceFilter::Event::Denm, MessageTraceFilter::Event::Dcc});
    }
    filter.setTypes({cl.messagesTypes.begin(), cl.messagesTypes.end()});
    return filter;
}

/// JSON Lines, or Parquet for *.parquet (pyarrow missing: a UsageError, before SUMO loads).
std::unique_ptr<TraceWriter> traceWriter(const CommandLine& cl, OutputFile& file, Scenario& scenario) {
    if (!cl.messagesParquet()) return std::make_unique<JsonLinesTrace>(file.stream());
    return std::make_unique<ParquetTrace>(scenario.parquetStream("--messages", file.descriptor()),
                                          fmt::format("--messages: cannot write '{}'", cl.messages->string()));
}

/// A type named in --messages-types that no station sent is most likely misspelt.
void warnOfUnsentTypes(const MessageTraceFilter& filter, const radio::Medium* medium) {
    if (medium == nullptr) return;
    std::vector<std::string> sent;
    for (const auto& [type, counts] : medium->counts()) {
        if (counts.sent > 0) sent.push_back(type);
    }
    for (const std::string& type : filter.types()) {
        if (std::find(sent.begin(), sent.end(), type) != sent.end()) continue;
        fmt::print(stderr, "sbsim: warning: --messages-types {}: no {} message was sent (sent: {})\n", type, type,
                   sent.empty() ? std::string("none") : fmt::format("{}", fmt::join(sent, ", ")));
    }
}

}  // namespace

/// SUMO warnings of one kind shown on stderr before they are only counted (--verbose: all).
constexpr std::size_t kWarningsShown = 3;

int RunCommand::run(const CommandLine& cl) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point started = Clock::now();

    const auto [sumocfg, story] = scenarioFiles(cl, !cl.noSnapshot);
    FileLedger files;
    checkSumoInputs(sumocfg, cl.sumoOptions, files);
    if (story) files.requireInput("--story", *story);
    // Plugins first: their services must be registered before the services file is checked.
    const std::vector<std::unique_ptr<PluginLibrary>> plugins = loadPlugins(cl.plugins, files);
    std::optional<services::ServicesConfig> servicesConfig;
    if (cl.services) servicesConfig = loadServicesConfig(*cl.services, files);
    checkRadioInput(cl, files);
    // Opened once every input is known, so it can be none of them; before SUMO loads, so a path
    // it cannot write fails at once.
    std::optional<OutputFile> events;
    if (cl.events) events.emplace("--events", *cl.events, files);
    std::optional<OutputFile> summary;
    if (cl.summary) summary.emplace("--summary", *cl.summary, files);
    std::optional<OutputFile> messages;
    if (cl.messages) {
        if (!cl.services) throw UsageError("--messages: there are no messages without --services");
        messages.emplace("--messages", *cl.messages, files);
    }
    std::optional<OutputFile> statisticsFile;
    if (cl.statistics) statisticsFile.emplace("--statistics", *cl.statistics, files);
    std::optional<OutputFile> junit;
    if (cl.junit) junit.emplace("--junit", *cl.junit, files);
    std::optional<OutputFile> sumoLog;
    if (cl.sumoLog) sumoLog.emplace("--sumo-log", *cl.sumoLog, files);
    std::optional<GuiWatch> gui;
    if (cl.gui) {
        GuiWatch::requireDisplay();
        gui.emplace(cl.guiScreenshots, files);
    }
    Interruption::checkpoint("before SUMO loaded");

    traffic::SumoSettings settings = Scenario::sumoSettings(cl, sumocfg);
    settings.warningsShown = cl.verbose ? SIZE_MAX : kWarningsShown;
    settings.readVehicles = !cl.noSnapshot;
    settings.gui = cl.gui;
    if (cl.gui) settings.beforeClose = &GuiWatch::wakeBeforeClose;
    if (cl.guiDelay)
        settings.extraOptions.insert(settings.extraOptions.end(), {"--delay", fmt::format("{:g}", *cl.guiDelay)});

    Scenario scenario(cl, settings, cl.threads);
    kernel::Simulation& sim = scenario.simulation();
    traffic::SumoBridge& sumo = scenario.sumo();
    if (statisticsFile) scenario.requireStatisticsFile();  // pyarrow missing: fail before the run
    // After the scenario: its Python finds the interpreter a Parquet trace is written with.
    std::optional<MessageTraceFile> messageTrace;
    if (messages) messageTrace.emplace(traceWriter(cl, *messages, scenario), traceFilter(cl), cl.messagesMaxBytes);
    const traffic::Penetration& penetration = scenario.equipment().penetration();
    if (sumoLog) sumo.warnings().setLog(&sumoLog->stream());
    scenario.loadSumo();
    Interruption::checkpoint("while SUMO was loading");
    if (settings.end && *settings.end < sumo.beginTime()) {
        throw UsageError(
            fmt::format("--end: {} s is before SUMO's begin time ({} s)", settings.end->str(), sumo.beginTime().str()));
    }

    std::optional<storyboard::EventLog> log;
    if (events) log.emplace(events->stream());
    // Equipment matters where V2X runs: the logs of runs without services stay as they were.
    if (log && servicesConfig) {
        scenario.equipment().onEquipped(
            [&log](kernel::SimTime t, const std::string& vehicle) { log->equipped(t, vehicle); });
    }
    if (messageTrace) scenario.stations().setPhaseSink(&*messageTrace);
    if (story) {
        storyboard::StoryScript& script = scenario.addStoryboard(
            *story, log ? &*log : nullptr,
            cl.storyboardEquippedOnly ? std::optional<traffic::Penetration>(penetration) : std::nullopt);
        scenario.board()->setWarmupEndTime(kernel::SimTime::fromSeconds(cl.warmup));
        std::size_t created = 0;
        untilInterrupted([&] { created = script.createStories(); });
        Interruption::reassert();  // the script may have set handlers of its own
        Interruption::checkpoint("while the story was being created");
        if (created == 0) fmt::print(stderr, "sbsim: warning: {} registered no story\n", story->string());
        // Without a service that sends DENMs (a vehicle's or a roadside unit's) no DENM memory
        // fills: such a criterion would fail every vehicle.
        // Asked only when a criterion needs it: a Python service's traits import its class.
        std::optional<bool> sendsDenms;
        const auto denmSource = [&] {
            if (sendsDenms) return *sendsDenms;
            const std::vector<const services::ServiceSpec*> all =
                servicesConfig ? servicesConfig->allServices() : std::vector<const services::ServiceSpec*>{};
            try {
                sendsDenms = std::any_of(all.begin(), all.end(), [](const services::ServiceSpec* s) {
                    return services::ServiceRegistry::instance().traits(*s).sendsDenms;
                });
            } catch (const services::ServicesConfigError& e) {  // a Python service's file or class
                throw InputError(fmt::format("--services: {}", e.what()));
            }
            return *sendsDenms;
        };
        for (const storyboard::CriterionPtr& c : scenario.board()->criteria()) {
            if (c->readsDenmMemory() && !denmSource()) {
                throw InputError(fmt::format(
                    "{}: criterion '{}' reads the vehicles' DENM memory, but no DEN service "
                    "runs (no service in --services sends DENMs, such as DenService, RsuDenService or a Python "
                    "service declaring sends_denms = True)",
                    story->string(), c->name()));
            }
        }
        // An id the network does not have would never match (or fail minutes in): refused now, as
        // `sbsim check` warns of it. Only the network questions are asked (the other checks warn).
        const NetworkQuestions network(RouteIds(SumoOptions(sumocfg, cl.sumoOptions).files("route-files")));
        storyboard::CheckScenario questions;
        network.answer(questions);
        for (const storyboard::CheckWarning& w : storyboard::checkStories(scenario.board()->stories(), questions)) {
            if (w.unknownId) throw InputError(fmt::format("{}: story '{}': {}", story->string(), w.story, w.message));
        }
        for (const storyboard::CheckWarning& w : storyboard::checkCriteria(scenario.board()->criteria(), questions)) {
            if (w.unknownId) {
                throw InputError(fmt::format("{}: criterion '{}': {}", story->string(), w.story, w.message));
            }
        }
    }
    storyboard::Storyboard* board = scenario.board();
    storyboard::StoryPainter painter;
    if (gui) {
        if (board != nullptr) {
            board->observeActivations(painter);
            gui->drawAreas(board->stories());
        }
        gui->attach(sumo);
    }

    if (servicesConfig) {
        std::vector<services::ServiceSpec> specs;
        for (const services::ServiceSpec* spec : servicesConfig->allServices()) specs.push_back(*spec);
        try {
            scenario.addServices(std::move(*servicesConfig), kernel::SimTime::fromSeconds(cl.middlewareInterval),
                                 penetration, messageTrace ? &*messageTrace : nullptr);
        } catch (const services::ServicesConfigError& e) {  // a Python service's file, class or attributes
            throw InputError(fmt::format("--services: {}", e.what()));
        }
        // Imported now: a Python service named by module has a file.
        addLoadedServiceFiles(specs, *cl.services, files);
        // Only when asked for: the default 0.1 s stays as it was, whatever the step length.
        if (cl.middlewareIntervalGiven && kernel::SimTime::fromSeconds(cl.middlewareInterval) < sumo.stepLength()) {
            fmt::print(
                stderr,
                "sbsim: warning: --middleware-interval {:g} s is shorter than SUMO's step length ({} s): services "
                "see the same vehicle positions several times\n",
                cl.middlewareInterval, sumo.stepLength().str());
        }
    }

    std::unique_ptr<ProgressDisplay> progress;
    if (!cl.quiet && isatty(STDERR_FILENO)) {
        progress = std::make_unique<ProgressDisplay>(stderr, sumo.endTime(), sumo.snapshot());
        sumo.subscribe(traffic::SumoBridge::stepSignal, *progress);
    }
    AfterEachStep checks([&] {
        Interruption::reassert();
        if (Interruption::requested()) sim.stop();
        if (events) events->check();  // a full disk ends the run now, not at its end
        if (messages) messages->check();
        // A full trace takes nothing more: the medium need not report (nor visit) anyone for it.
        if (messageTrace && messageTrace->full() && scenario.medium() != nullptr) {
            scenario.medium()->setTrace(nullptr);
            scenario.stations().setPhaseSink(nullptr);
        }
    });
    sim.subscribe(traffic::SumoBridge::stepSignal, checks);
    try {
        untilInterrupted([&] { sim.run(); });
        untilInterrupted([&] { sim.finish(); });
    } catch (const traffic::SumoError& e) {
        throw InputError(fmt::format("SUMO error in '{}' at t={} s: {}", sumocfg.string(), sim.now().str(), e.what()));
    } catch (const libsumo::TraCIException& e) {
        throw InputError(fmt::format("SUMO error at t={} s: {}", sim.now().str(), e.what()));
    } catch (const services::ServiceError& e) {
        throw InputError(e.what());  // the user's code, like a story's error
    } catch (const services::ServicesConfigError& e) {
        // A service reads its parameters when its first vehicle departs: still bad input.
        throw InputError(fmt::format("--services: {}", e.what()));
    }
    // Judged once, at the end: a Python criterion's error is the story's (exit 2).
    std::vector<std::pair<std::string, storyboard::CriterionVerdict>> verdicts;
    if (board != nullptr) untilInterrupted([&] { verdicts = board->verdicts(); });
    const bool criterionFailed =
        std::any_of(verdicts.begin(), verdicts.end(), [](const auto& v) { return !v.second.passed; });
    if (progress) progress->clear();
    if (gui && !Interruption::requested()) gui->finish(sim.now());
    // Everything written first, then committed together: a failure in any output (a full disk,
    // the Parquet writer) or an interruption while they are written leaves all of them
    // .incomplete, none under its final name.
    if (messageTrace) {
        messageTrace->finish(sim.now());
        if (!Interruption::requested()) warnOfUnsentTypes(messageTrace->filter(), scenario.medium());
    }
    if (junit) {
        writeJUnit(junit->stream(), story ? story->filename().string() : sumocfg.filename().string(), verdicts,
                   std::chrono::duration<double>(Clock::now() - started).count());
    }
    if (statisticsFile) statisticsFile->stream() << scenario.statisticsFile();

    const RunFigures figures{sumocfg,
                             sim,
                             sumo,
                             board,
                             scenario.services(),
                             scenario.medium(),
                             &scenario.statistics(),
                             verdicts,
                             std::chrono::duration<double>(Clock::now() - started).count(),
                             cl.arguments,
                             messageTrace ? std::optional(messageTrace->figures()) : std::nullopt,
                             scenario.obstacles() ? &*scenario.obstacles() : nullptr,
                             scenario.services() != nullptr ? &scenario.equipment() : nullptr};
    if (summary) summary->stream() << summaryJson(figures).dump(2) << '\n';
    // Only a run that ended as it should gives outputs their names; others stay .incomplete.
    const auto present = [](std::optional<OutputFile>& f) { return f ? &*f : nullptr; };
    if (!Interruption::requested()) {
        commitTogether({present(events), present(messages), present(sumoLog), present(junit), present(statisticsFile),
                        present(summary)});
    }
    if (!cl.quiet) {
        try {
            printSummary(figures);
        } catch (const std::system_error& e) {
            if (e.code().value() != EPIPE) throw;  // nobody reads stdout any more: the run is still done
        }
        std::fflush(stdout);
    }
    if (story) {
        const std::vector<std::string> lingering = scenario.abandonLingeringThreads();
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
    // 130: the shell's convention for SIGINT; 3: a criterion failed (the run itself went well).
    const int exitCode = Interruption::requested() ? 130 : criterionFailed ? 3 : 0;
    if (Interruption::requested()) fmt::print(stderr, "sbsim: interrupted at t={} s\n", sim.now().str());
    if (gui) GuiWatch::closeWithin(sumo, std::chrono::seconds(10), exitCode);
    return exitCode;
}

}  // namespace sbsim::app
