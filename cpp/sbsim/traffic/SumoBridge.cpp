#include "sbsim/traffic/SumoBridge.h"

#include <libsumo/Simulation.h>
#include <libsumo/Vehicle.h>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "sbsim/kernel/OneLine.h"

namespace sbsim::traffic {

namespace {
/// SUMO's printed "Error: ..." lines folded into one line, or the exception text if there are none.
std::string sumoErrorLine(const std::string& printed, const std::string& fallback) {
    std::string line;
    std::size_t pos = 0;
    bool inError = false;
    while (pos < printed.size()) {
        std::size_t eol = printed.find('\n', pos);
        if (eol == std::string::npos) eol = printed.size();
        std::string text = printed.substr(pos, eol - pos);
        pos = eol + 1;
        if (text.rfind("Error: ", 0) == 0) {
            inError = true;
            text.erase(0, 7);
        } else if (text.rfind("Warning: ", 0) == 0) {
            inError = false;
            continue;
        }
        if (!inError) continue;
        const std::size_t first = text.find_first_not_of(" \t");
        if (first == std::string::npos) continue;
        if (!line.empty()) line += ' ';
        line += text.substr(first);
    }
    return kernel::oneLine(line.empty() ? fallback : line);
}

/// Runs `call` with stderr captured. Returns nothing if it succeeded (having handed what SUMO
/// printed to `warnings`), else SUMO's error as one line. Every exception
/// counts: libsumo's, and SUMO's own ProcessErrors, which are plain std::runtime_errors.
template <typename F>
std::optional<std::string> capturingErrors(StderrCapture& capture, SumoWarnings& warnings, F call) {
    std::optional<std::string> failure;
    capture.start();
    try {
        call();
    } catch (const std::exception& e) {
        failure = e.what();
    } catch (...) {
        failure = "unknown error";
    }
    const std::string printed = capture.stop();
    if (failure) return sumoErrorLine(printed, failure->empty() ? "unknown error" : *failure);
    if (!printed.empty()) warnings.take(printed);
    return std::nullopt;
}
}  // namespace

const kernel::SignalId SumoBridge::departedSignal = kernel::registerSignal("vehicleDeparted");
const kernel::SignalId SumoBridge::arrivedSignal = kernel::registerSignal("vehicleArrived");
const kernel::SignalId SumoBridge::stepSignal = kernel::registerSignal("sumoStep");

SumoBridge::SumoBridge(SumoSettings settings)
    : kernel::Module("sumo"), settings_(std::move(settings)), warnings_(settings_.warningsShown) {
    stepMessage_.setPriority(kStepPriority);
    endMessage_.setPriority(std::numeric_limits<int>::max());
    builder_.setColumns(demanded_);  // nothing until a reader asks
}

SumoBridge::~SumoBridge() { close(); }

void SumoBridge::load() {
    if (loaded_) return;
    const std::vector<std::string>& extra = settings_.extraOptions;
    // SUMO refuses an option given twice, so sbsim's defaults yield to the user's.
    const auto defaultOption = [&](std::vector<std::string>& args, const std::string& name, const std::string& value) {
        if (std::find(extra.begin(), extra.end(), name) == extra.end()) args.insert(args.end(), {name, value});
    };
    std::vector<std::string> args = {"-c", settings_.sumocfg.string()};
    defaultOption(args, "--no-step-log", "true");
    if (settings_.seed) args.insert(args.end(), {"--seed", std::to_string(*settings_.seed)});
    if (settings_.quiet) defaultOption(args, "--no-warnings", "true");
    args.insert(args.end(), extra.begin(), extra.end());

    const auto start = [&] {
        if (!settings_.gui) return libsumo::Simulation::load(args);
        // libsumo opens its GUI when the program name is sumo-gui; stepping and the API stay the same.
        std::vector<std::string> command{"sumo-gui"};
        command.insert(command.end(), args.begin(), args.end());
        libsumo::Simulation::start(command);
    };
    if (const auto failure = capturingErrors(capture_, warnings_, start)) {
        throw SumoLoadError(*failure);
    }
    loaded_ = true;
    try {
        checkTimes(libsumo::Simulation::getTime(), libsumo::Simulation::getEndTime());
    } catch (const SumoLoadError&) {
        close();
        throw;
    }

    stepLength_ = kernel::SimTime::fromSeconds(libsumo::Simulation::getDeltaT());
    builder_.setStepLength(libsumo::Simulation::getDeltaT());
    begin_ = kernel::SimTime::fromMilliseconds(libsumo::Simulation::getCurrentTime());
    const double configuredEnd = libsumo::Simulation::getEndTime();
    end_ = settings_.end;
    if (!end_ && configuredEnd >= 0) end_ = kernel::SimTime::fromSeconds(configuredEnd);
    const libsumo::TraCIPositionVector b = libsumo::Simulation::getNetBoundary();
    if (b.value.size() >= 2) boundary_ << b.value[0].x, b.value[1].x, b.value[0].y, b.value[1].y;
}

void SumoBridge::checkTimes(double begin, double end) {
    // Beyond these, sbsim's nanosecond clock would overflow (SUMO's millisecond one does not).
    if (!(std::fabs(begin) <= kMaxSeconds)) {
        throw SumoLoadError(
            fmt::format("the begin time {:g} s is beyond what sbsim runs (at most {:g} s)", begin, kMaxSeconds));
    }
    if (!(end <= kMaxSeconds)) {
        throw SumoLoadError(
            fmt::format("the end time {:g} s is beyond what sbsim runs (at most {:g} s)", end, kMaxSeconds));
    }
}

void SumoBridge::initialize() {
    load();
    // The kernel's clock starts where SUMO does, so the modules initialized after the bridge (services,
    // media) start their timers at the run's begin, not at 0 s.
    simulation().startAt(begin_);
    // Vehicles already on the road (a loaded state) count as departed at the beginning.
    std::vector<std::string> present = libsumo::Vehicle::getIDList();
    std::sort(present.begin(), present.end());
    builder_.addVehicles(present);
    vehiclesSeen_ += present.size();
    peakRunning_ = builder_.running();
    builder_.fill(snapshot_, begin_, simulation().parallel());
    announce(present, departedSignal);
    scheduleNextStep();
}

void SumoBridge::scheduleNextStep() {
    // The run ends after the step that reaches the end time (as SUMO's own --end does).
    const kernel::SimTime current = begin_ + stepLength_ * static_cast<kernel::SimTime::rep>(steps_);
    if (end_ && current >= *end_) return endRun(EndReason::EndTime);
    scheduleAt(current + stepLength_, stepMessage_);
}

void SumoBridge::endRun(EndReason reason) {
    endReason_ = reason;
    // Everything else due now (services, radio messages) still happens before the run stops.
    scheduleAt(simTime(), endMessage_);
}

void SumoBridge::announce(const std::vector<std::string>& ids, kernel::SignalId signal) {
    for (const std::string& id : ids) emit(signal, std::string_view(id));
}

void SumoBridge::handleMessage(kernel::Message& msg) {
    if (&msg == &endMessage_) return simulation().stop();
    if (&msg != &stepMessage_) return kernel::Module::handleMessage(msg);
    using Clock = std::chrono::steady_clock;
    const Clock::time_point started = Clock::now();
    // A vehicle a command removed since the last step (a world story's closure takes out one SUMO
    // inserted in that step) arrived then. (One removed before it departed never ran: it neither
    // departs nor arrives.) Nothing to do in a step unless a command removed one.
    std::vector<std::string> arrived;
    arrived.swap(removedByCommand_);
    std::erase_if(arrived, [this](const std::string& id) { return !builder_.isRunning(id); });
    step();
    const Clock::time_point stepped = Clock::now();
    ++steps_;
    std::vector<std::string> departed = libsumo::Simulation::getDepartedIDList();
    std::sort(departed.begin(), departed.end());
    const std::vector<std::string> sumoArrived = libsumo::Simulation::getArrivedIDList();
    arrived.insert(arrived.end(), sumoArrived.begin(), sumoArrived.end());
    std::sort(arrived.begin(), arrived.end());
    builder_.addVehicles(departed);
    builder_.removeVehicles(arrived);
    vehiclesSeen_ += departed.size();
    peakRunning_ = std::max(peakRunning_, builder_.running());
    if (settings_.readVehicles) builder_.fill(snapshot_, simTime(), simulation().parallel());
    sumoSeconds_ += std::chrono::duration<double>(stepped - started).count();
    snapshotSeconds_ += std::chrono::duration<double>(Clock::now() - stepped).count();

    announce(departed, departedSignal);
    announce(arrived, arrivedSignal);
    emit(stepSignal, static_cast<const kernel::Object&>(snapshot_));

    if (libsumo::Simulation::getMinExpectedNumber() <= 0) return endRun(EndReason::NoMoreVehicles);
    scheduleNextStep();
}

void SumoBridge::demandColumns(SnapshotColumns columns) {
    demanded_ |= columns;
    builder_.setColumns(demanded_);
}

std::string SumoBridge::sumoVersion() const { return libsumo::Simulation::getVersion().second; }

void SumoBridge::step() {
    if (const auto failure = capturingErrors(capture_, warnings_, [] { libsumo::Simulation::step(); })) {
        throw SumoError(*failure);
    }
}

// SUMO stays loaded until the bridge is destroyed, so other modules' finish() can still ask it
// about their vehicles; the destructor closes it whatever happened.
void SumoBridge::finish() {}

void SumoBridge::close() {
    if (!loaded_) return;
    loaded_ = false;
    try {
        if (settings_.beforeClose) settings_.beforeClose();
        libsumo::Simulation::close();
    } catch (const std::exception&) {
        // Closing is best effort: SUMO may already have shut down after a fatal error.
    }
}

}  // namespace sbsim::traffic
