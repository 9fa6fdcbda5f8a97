#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/ParallelFor.h"
#include "sbsim/storyboard/ActivationObserver.h"
#include "sbsim/storyboard/EvaluationContext.h"
#include "sbsim/storyboard/EventLog.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/traffic/EffectStack.h"
#include "sbsim/traffic/StoryboardSignal.h"
#include "sbsim/traffic/VehicleController.h"
#include "sbsim/traffic/VehicleRegistry.h"

namespace sbsim::storyboard {

/// The board's pass over the vehicles, in Artery's order: vehicles in ascending byte order of id,
/// for each vehicle every story about vehicles in registration order. A story whose condition
/// turns true for a vehicle is activated for it (effects applied, in order); one whose condition
/// turns false is deactivated (effects removed, in reverse order). Stories whose whole tree is pure
/// (no state, no side effects) are evaluated for every vehicle up front, in parallel; that changes
/// nothing but the time, since only the ordered pass acts on the results.
class SBSIM_API VehiclePass {
public:
    /// Events go to `log` from now on (a log the board made when a criterion reads events).
    void setLog(EventLog* log) { log_ = log; }
    /// Where SignalEffects' signals go (the board emits them as kernel signals).
    struct SignalOutlet {
        std::function<bool()> listened;  ///< whether anyone would hear one (else none is built)
        std::function<void(const traffic::StoryboardSignal&)> send;
    };

    /// Vehicles are commanded through `registry`; events go to `log` (optional).
    VehiclePass(SignalOutlet signals, traffic::VehicleRegistry& registry, EventLog* log);
    ~VehiclePass();
    VehiclePass(const VehiclePass&) = delete;
    VehiclePass& operator=(const VehiclePass&) = delete;

    /// Adds a story about vehicles, the board's `boardIndex`-th.
    void addStory(Story& story, std::size_t boardIndex);
    /// `observer` sees every activation (and may dress it with an effect).
    void observe(ActivationObserver& observer) { observer_ = &observer; }

    /// The vehicle left: each story active on it is deactivated with reason "vehicle_left" (no
    /// commands to SUMO: there is nothing left to command; its effects hear vehicleLeft()) and its
    /// state dropped.
    void vehicleLeft(const std::string& id, kernel::SimTime now);
    /// Evaluates every story for every vehicle of ctx's snapshot, on `parallel` where pure.
    void run(const EvaluationContext& ctx, kernel::ParallelFor& parallel);
    /// Vehicles of this step's snapshot that run() leaves alone: a world story removed them from
    /// SUMO in this step, right after SUMO inserted them (sorted; until the next call).
    void setGone(std::vector<std::string> ids) { gone_ = std::move(ids); }

    bool isActive(const std::string& vehicle, const Story& story) const;
    /// Vehicles the pass keeps state for (effect stacks, activations): never more than are running.
    std::size_t vehicleStates() const { return vehicles_.size(); }
    /// How many signals SignalEffects emitted, by cause.
    const std::map<std::string, std::uint64_t, std::less<>>& signalsByCause() const { return signalsByCause_; }

private:
    struct Entry {
        Story* story;
        std::size_t boardIndex;
        bool pure;                     // its whole tree is pure
        std::uint64_t maxActivations;  // per vehicle (max: unlimited)
    };
    struct AppliedEffect {
        Effect* effect;
        traffic::EffectStack::Token token;
    };
    struct VehicleState {
        /// The vehicle's one controller and effect stack (the services' too).
        std::shared_ptr<traffic::VehicleRegistry::Vehicle> vehicle;
        /// vehicle's controller, shared with the weak VehicleHandles given to scripts: they lapse
        /// when the pass lets go of the vehicle, after it left.
        std::shared_ptr<traffic::VehicleController> controller;
        std::vector<std::vector<AppliedEffect>> applied;  // per story; non-empty iff active
        std::vector<bool> active;                         // per story
        std::vector<std::uint64_t> activations;           // per story: how often it activated for the vehicle
    };
    /// A vehicle of the current pass, by snapshot index.
    struct Row {
        VehicleState* state = nullptr;  // none until a story first activates for it
        bool settling = false;          // its stack holds its speed or lane (settle() each step)
    };
    class Scope;

    VehicleState& stateFor(const std::string& id);
    void matchStates(const traffic::VehicleSnapshot& snapshot);
    void forgetRow(const std::string& id);
    void copyFlags(const VehicleState& state, std::uint8_t* row) const;
    void activate(VehicleState& state, std::size_t story, const std::string& id, const ConditionResult& result,
                  const traffic::VehicleSnapshot& snapshot);
    void deactivate(VehicleState& state, std::size_t story, const std::string& id);
    void applyEffect(Scope& scope, const Story& story, std::vector<AppliedEffect>& applied, Effect& effect);

    SignalOutlet signals_;
    traffic::VehicleRegistry& registry_;
    EventLog* log_;
    ActivationObserver* observer_ = nullptr;
    kernel::SimTime now_;
    std::vector<std::string> gone_;
    std::vector<Entry> stories_;
    std::vector<std::size_t> pureStories_;                    // indices into stories_
    std::vector<std::vector<ConditionResult>> precomputed_;   // per story (pure ones), per vehicle of the step
    std::unordered_map<std::string, VehicleState> vehicles_;  // vehicles with state (node-stable)
    // The last pass's vehicles by snapshot index (ids ascending), carried over by matchStates().
    std::vector<std::string> stateIds_;
    std::uint64_t stateIdsVersion_ = 0;  // VehicleSnapshot::idsVersion() of stateIds_
    std::vector<Row> rows_;
    std::vector<std::uint8_t> activeFlags_;  // rows_.size() × flagStride_: story active for the vehicle
    std::size_t flagStride_ = 0;
    std::vector<Row> rowScratch_;
    std::vector<std::uint8_t> flagScratch_;
    std::map<std::string, std::uint64_t, std::less<>> signalsByCause_;
};

}  // namespace sbsim::storyboard
