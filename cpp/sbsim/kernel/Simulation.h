#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <type_traits>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/FutureEventSet.h"
#include "sbsim/kernel/ParallelFor.h"
#include "sbsim/kernel/RandomStream.h"
#include "sbsim/kernel/Signal.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/kernel/StudyParameters.h"

namespace sbsim::kernel {

class Module;

/// The event loop: owns the modules and the future-event set, advances time from event to event
/// (never between them), and runs the lifecycle. Deterministic: the same inputs deliver the same
/// events in the same order. It also owns what the whole process shares: one pool of worker
/// threads for per-vehicle loops, and the seeded random streams.
class SBSIM_API Simulation {
public:
    enum class StopReason { NoMoreEvents, TimeLimit, Requested };

    /// `seed` seeds every random stream; `threads` is the pool's size, the caller included
    /// (0 = all cores).
    explicit Simulation(std::uint64_t seed = 0, unsigned threads = 1);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    /// Adds a module; if the simulation is already initialized the module is initialized now.
    Module& addModule(std::unique_ptr<Module> module);
    template <typename T, typename... Args>
    T& emplaceModule(Args&&... args) {
        static_assert(std::is_base_of_v<Module, T>);
        return static_cast<T&>(addModule(std::make_unique<T>(std::forward<Args>(args)...)));
    }
    /// Calls finish() on a module if it was initialized, drops its pending events and destroys it.
    void removeModule(Module& module);
    std::size_t moduleCount() const { return modules_.size(); }

    SimTime now() const { return now_; }
    std::uint64_t eventCount() const { return events_; }
    /// Modules added plus modules removed so far: pointers to modules taken while it is unchanged
    /// are all still valid, and nothing new joined.
    std::uint64_t moduleChanges() const { return moduleChanges_; }
    FutureEventSet& futureEvents() { return fes_; }
    /// Simulation-wide listeners: they hear every module's emits.
    SignalTable& signals() { return signals_; }
    void subscribe(SignalId id, Listener& listener) { signals_.subscribe(id, listener); }

    /// The process's worker threads: modules run their per-vehicle loops here, one round at a time.
    ParallelFor& parallel() { return parallel_; }
    std::uint64_t seed() const { return seed_; }
    /// Random stream `index`, seeded by seed(); the same index always gives the same stream, so a
    /// module drawing from its own index never shifts another's draws.
    std::shared_ptr<RandomStream> randomStream(unsigned index);
    /// The run's study parameters (--param), read by stories and services alike.
    StudyParameters& parameters() { return parameters_; }
    const StudyParameters& parameters() const { return parameters_; }

    /// Sets the clock to `begin` before the run: a run that begins later than 0 s (SUMO's --begin, a
    /// loaded state) starts its timers there instead of firing every period missed since 0 s at once.
    /// Allowed until the first event is delivered; throws std::logic_error after that, or if an event
    /// is already scheduled before `begin`.
    void startAt(SimTime begin);
    /// initialize() on every module, in the order they were added.
    void initialize();
    /// Delivers events in order while their time is <= `limit`.
    StopReason run(SimTime limit = SimTime::max());
    /// Ends run() after the event being handled; called outside an event (e.g. from initialize()),
    /// the next run() returns before delivering any.
    void stop() { stopRequested_ = true; }
    /// finish() on every initialized module, in the order they were added; runs once.
    void finish();

    // Used by Module.
    void schedule(Message& msg, SimTime at, Module& target);
    void schedule(std::unique_ptr<Message> msg, SimTime at, Module& target);

private:
    std::uint64_t seed_;
    ParallelFor parallel_;
    std::map<unsigned, std::shared_ptr<RandomStream>> streams_;
    StudyParameters parameters_;
    std::vector<std::unique_ptr<Module>> modules_;
    FutureEventSet fes_;
    SignalTable signals_;
    SimTime now_;
    std::uint64_t events_ = 0;
    std::uint64_t moduleChanges_ = 0;
    bool initialized_ = false;
    bool finished_ = false;
    bool stopRequested_ = false;
};

}  // namespace sbsim::kernel
