#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Module.h"
#include "sbsim/traffic/SnapshotBuilder.h"
#include "sbsim/traffic/StderrCapture.h"
#include "sbsim/traffic/SumoWarnings.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::traffic {

/// What to load into SUMO and how long to run it.
struct SBSIM_API SumoSettings {
    std::filesystem::path sumocfg;
    std::vector<std::string> extraOptions;  ///< passed to SUMO as they are, after sbsim's own
    std::optional<std::int64_t> seed;       ///< SUMO's --seed
    std::optional<kernel::SimTime> end;     ///< default: the configuration's end, else until no vehicle is left
    bool quiet = false;                     ///< also silences SUMO's warnings
    std::size_t warningsShown = 3;          ///< SUMO warnings of one kind shown on stderr (SIZE_MAX: all)
    /// False: step SUMO without reading vehicle states (the snapshot keeps only ids) — a
    /// baseline that shows libsumo's own cost against the sumo binary.
    bool readVehicles = true;
    /// Start SUMO's GUI (sumo-gui inside this process, libsumo's GUI) instead of plain SUMO; an
    /// X display must be reachable, or FOX ends the process.
    bool gui = false;
    /// Called right before SUMO is closed (sbsim --gui wakes the GUI's event loop there).
    std::function<void()> beforeClose;
};

/// An error SUMO reported, as one line: its exception's message, or the "Error:" lines it printed
/// (which name the file and line where SUMO knows them).
class SBSIM_API SumoError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Raised when SUMO refuses the configuration (or sbsim refuses what SUMO loaded).
class SBSIM_API SumoLoadError : public SumoError {
public:
    using SumoError::SumoError;
};

/// Drives SUMO through libsumo as a kernel module: one self-message per SUMO step. After each step
/// it refreshes the vehicle snapshot and emits, in this order, `departedSignal` (one per vehicle,
/// value: id), `arrivedSignal` (one per vehicle, value: id) and `stepSignal` (value: the snapshot).
/// Vehicles are reported in ascending byte order of id. The run stops after the step that reaches
/// the end time, or when SUMO expects no more vehicles, once every other event due at that time has
/// been delivered. SUMO is closed by the destructor, whatever happened (not in finish(): other
/// modules' finish() may still ask SUMO about their vehicles). Whatever SUMO throws from a step
/// (libsumo's exceptions and its own ProcessErrors alike) comes out as a SumoError.
class SBSIM_API SumoBridge : public kernel::Module {
public:
    static const kernel::SignalId departedSignal;
    static const kernel::SignalId arrivedSignal;
    static const kernel::SignalId stepSignal;

    /// Steps come before other events due at the same time, so everything at time t sees step t.
    static constexpr int kStepPriority = -1000;
    /// The latest begin or end time sbsim runs (about 95 years): every step must fit its clock.
    static constexpr double kMaxSeconds = 3.0e9;

    enum class EndReason { Running, EndTime, NoMoreVehicles };

    explicit SumoBridge(SumoSettings settings);
    ~SumoBridge() override;

    /// Loads SUMO now (initialize() does it otherwise); throws SumoLoadError with SUMO's message,
    /// or if the begin or end time is beyond kMaxSeconds.
    void load();
    bool loaded() const { return loaded_; }

    void initialize() override;
    void handleMessage(kernel::Message& msg) override;
    void finish() override;

    const VehicleSnapshot& snapshot() const { return snapshot_; }
    /// Adds `columns` to what the snapshot reads from the next step on. Each reader declares what it
    /// reads (the storyboard its conditions', the services manager its services'); nothing is read
    /// per vehicle unless someone asked for it.
    void demandColumns(SnapshotColumns columns);
    kernel::SimTime stepLength() const { return stepLength_; }
    kernel::SimTime beginTime() const { return begin_; }
    /// The time the run stops at, if any (from --end or the configuration).
    std::optional<kernel::SimTime> endTime() const { return end_; }
    /// SUMO's network boundary: (xmin, ymin), (xmax, ymax).
    const Eigen::Matrix2d& netBoundary() const { return boundary_; }
    EndReason endReason() const { return endReason_; }

    std::uint64_t steps() const { return steps_; }
    std::uint64_t vehiclesSeen() const { return vehiclesSeen_; }
    std::size_t peakRunning() const { return peakRunning_; }
    /// Wall-clock seconds spent inside SUMO's steps and reading the snapshot (profiling figures).
    double sumoSeconds() const { return sumoSeconds_; }
    /// SUMO's version string, e.g. "SUMO v1_28_0" (asked of libsumo; SUMO must be loaded).
    std::string sumoVersion() const;
    double snapshotSeconds() const { return snapshotSeconds_; }
    /// A command took `id` out of SUMO since the last step (NetworkController::removeVehicle: a
    /// closure removes a vehicle SUMO inserted in that step). If it was running it arrived then, and
    /// is reported with the next step's arrivals: libsumo lists such a removal only until that step
    /// begins, and asking it every step would cost every run what only closures need.
    void removedByCommand(std::string id) { removedByCommand_.push_back(std::move(id)); }
    /// What VehicleControllers tell of max-speed changes (the snapshot reads max speeds only then).
    MaxSpeedListener& maxSpeedListener() { return builder_; }
    /// SUMO's warnings so far, by kind (set a log on it before load() to keep them all).
    SumoWarnings& warnings() { return warnings_; }
    const SumoWarnings& warnings() const { return warnings_; }

    /// Closes SUMO now (the destructor does otherwise); nothing after this may ask SUMO anything.
    void close();

private:
    void checkTimes(double begin, double end);
    void step();
    void scheduleNextStep();
    void endRun(EndReason reason);
    void announce(const std::vector<std::string>& ids, kernel::SignalId signal);

    SumoSettings settings_;
    bool loaded_ = false;
    kernel::SimTime stepLength_;
    kernel::SimTime begin_;
    std::optional<kernel::SimTime> end_;
    Eigen::Matrix2d boundary_ = Eigen::Matrix2d::Zero();
    kernel::Message stepMessage_{"sumo step"};
    kernel::Message endMessage_{"end of run"};
    SnapshotBuilder builder_;
    std::vector<std::string> removedByCommand_;  // since the last step
    SnapshotColumns demanded_;
    VehicleSnapshot snapshot_;
    StderrCapture capture_;
    SumoWarnings warnings_;
    EndReason endReason_ = EndReason::Running;
    std::uint64_t steps_ = 0;
    std::uint64_t vehiclesSeen_ = 0;
    std::size_t peakRunning_ = 0;
    double sumoSeconds_ = 0;
    double snapshotSeconds_ = 0;
};

}  // namespace sbsim::traffic
