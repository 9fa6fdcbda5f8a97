#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Module.h"
#include "sbsim/kernel/RandomStream.h"
#include "sbsim/storyboard/EventLog.h"
#include "sbsim/storyboard/NetworkStack.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/WorldStory.h"
#include "sbsim/traffic/EffectStack.h"
#include "sbsim/traffic/NeighbourGrid.h"
#include "sbsim/traffic/NetworkController.h"
#include "sbsim/traffic/Penetration.h"
#include "sbsim/traffic/TrafficQueries.h"
#include "sbsim/traffic/VehicleController.h"
#include "sbsim/traffic/VehicleRegistry.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::traffic {
class SumoBridge;
}

namespace sbsim::storyboard {

/// Evaluates the registered stories after every SUMO step, in Artery's order: vehicles in
/// ascending byte order of id, for each vehicle every story in registration order. A story whose
/// condition turns true for a vehicle is activated for it (effects applied, in order); one whose
/// condition turns false is deactivated (effects removed, in reverse order). Before that pass,
/// every active story of every vehicle that left is deactivated with reason "vehicle_left" and
/// its state dropped, without commands to SUMO. Stories whose conditions are all pure (no state,
/// no side effects) are evaluated for every vehicle up front, in parallel; that changes nothing
/// but the time, since only the ordered pass acts on the results.
///
/// WorldStories are evaluated once per step, in registration order, after the vehicles that left
/// and before the per-vehicle pass: the network the step's vehicle stories act on is then the one
/// the world stories made for that step (a closure's re-routing is done before a vehicle story
/// commands the vehicle, a vehicle spawned at t is known to SUMO from t on). Their conditions see
/// a world of one row with the id "" (no SUMO vehicle has that id), so Hold and Rising keep their
/// state for the world apart from any vehicle's.
class SBSIM_API Storyboard : public kernel::Module, private kernel::Listener {
public:
    using ControllerFactory = traffic::VehicleRegistry::ControllerFactory;

    /// `log` (optional) receives the event lines. Random streams and the threads evaluating pure
    /// stories are the simulation's.
    explicit Storyboard(EventLog* log = nullptr);
    ~Storyboard() override;

    /// Listen to `sumo`'s arrivals and steps (a SumoBridge); without this call, drive update() by hand.
    /// A SumoBridge is also told which snapshot values the stories read, now and as stories come
    /// (and the board's own registry, if it has one, is attached to it).
    void attach(kernel::Module& sumo);
    /// Commands vehicles through `registry`'s controllers and effect stacks, shared with the
    /// services (default: a registry of the board's own). Call before the first update().
    void useRegistry(traffic::VehicleRegistry& registry);
    /// The snapshot values the registered stories read (none without stories).
    traffic::SnapshotColumns columns() const;
    /// Replaces how vehicles are commanded (default: libsumo through traffic::VehicleController),
    /// in the registry the board uses.
    void setControllerFactory(ControllerFactory factory) { registry_->setControllerFactory(std::move(factory)); }
    /// Replaces how world effects command the network (default: libsumo).
    void setNetworkController(std::unique_ptr<traffic::NetworkController> network);
    /// Replaces what conditions ask of the traffic beyond the snapshot (default: libsumo).
    void setTrafficQueries(std::unique_ptr<traffic::TrafficQueries> queries) { queries_ = std::move(queries); }

    /// Artery's warm-up period, as scripts ask for it (getWarmupEndTime); it changes nothing else.
    void setWarmupEndTime(kernel::SimTime t) { warmupEnd_ = t; }
    /// Stories see only the vehicles `penetration` equips, as egos and as others
    /// (--storyboard-equipped-only); by default they see every vehicle.
    void seeEquippedOnly(const traffic::Penetration& penetration) { equippedOnly_ = penetration; }
    kernel::SimTime warmupEndTime() const { return warmupEnd_; }
    /// Shows which story acts on a vehicle (`sbsim --gui`): while a story is active on a vehicle,
    /// the vehicle takes the story's colour (storyColour of its registration index). The colour is
    /// applied before the story's own effects, as one more colour effect on the vehicle's stack,
    /// so a ColorEffect of the story wins over it, the latest activated story's colour wins among
    /// stories, and the vehicle's own colour comes back when none is active.
    void paintStories() { paintStories_ = true; }

    void registerStory(StoryPtr story);
    const std::vector<StoryPtr>& stories() const { return stories_; }
    /// Random stream k of the simulation (Artery scripts pass the generator index).
    std::shared_ptr<kernel::RandomStream> randomStream(unsigned k) { return simulation().randomStream(k); }

    /// One evaluation pass: first the vehicles in `left` (any order), then every vehicle of `snapshot`.
    void update(const traffic::VehicleSnapshot& snapshot, std::vector<std::string> left);

    bool isActive(const std::string& vehicle, const Story& story) const;
    /// Whether the WorldStory `story` is active now.
    bool isActive(const Story& story) const;
    /// The network's composition of world effects (closed edges, held signals).
    const NetworkStack& network() const { return *networkStack_; }
    /// Wall-clock seconds spent in update() (a profiling figure for the summary).
    double updateSeconds() const { return updateSeconds_; }
    /// How many signals SignalEffects emitted, by cause (the summary's figures).
    const std::map<std::string, std::uint64_t, std::less<>>& signalsByCause() const { return signalsByCause_; }
    /// Vehicles the board keeps state for (effect stacks, activations): never more than are running.
    std::size_t vehicleStates() const { return vehicles_.size(); }
    /// The most vehicles any one condition keeps state for (Hold, Likelihood, Limit, ...).
    std::size_t maxConditionStates() const;

private:
    struct AppliedEffect {
        Effect* effect;
        traffic::EffectStack::Token token;
    };
    struct VehicleState {
        /// The vehicle's one controller and effect stack (the services' too).
        std::shared_ptr<traffic::VehicleRegistry::Vehicle> vehicle;
        /// vehicle's controller, shared with the weak VehicleHandles given to scripts: they lapse
        /// when the board lets go of the vehicle, after it left.
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
    class WorldScopeImpl;
    struct WorldState {
        bool active = false;
        std::vector<std::pair<WorldEffect*, NetworkStack::Token>> applied;  // non-empty iff active
    };

    void receiveSignal(kernel::Module& source, kernel::SignalId id, std::string_view value) override;
    void receiveSignal(kernel::Module& source, kernel::SignalId id, const kernel::Object& value) override;

    VehicleState& stateFor(const std::string& id);
    void matchStates(const std::vector<std::string>& ids);
    void forgetState(const std::string& id);
    void copyFlags(const VehicleState& state, std::uint8_t* row) const;
    void activate(VehicleState& state, std::size_t story, const std::string& id, const ConditionResult& result,
                  const traffic::VehicleSnapshot& snapshot);
    void deactivate(VehicleState& state, std::size_t story, const std::string& id);
    void collectConditions(Condition& root);
    void updateWorld();
    void activateWorld(std::size_t story);
    void deactivateWorld(std::size_t story);
    void applyEffect(Scope& scope, std::vector<AppliedEffect>& applied, Effect& effect);
    Effect& paintOf(std::size_t story);

    EventLog* log_;
    traffic::SumoBridge* bridge_ = nullptr;  // the attached SUMO, told what the stories read
    kernel::SimTime now_;
    bool updated_ = false;  ///< a pass has run: now_ is a step's time
    std::vector<StoryPtr> stories_;
    std::vector<bool> pure_;                 // per story: its whole tree is pure
    std::vector<bool> world_;                // per story: a WorldStory
    std::vector<std::size_t> worldStories_;  // indices of the WorldStories
    std::vector<WorldState> worldStates_;    // per story (used for WorldStories)
    std::unique_ptr<traffic::NetworkController> network_;
    std::unique_ptr<NetworkStack> networkStack_;
    traffic::VehicleSnapshot worldSnapshot_;  // the world's one row, at the step's time
    traffic::NeighbourGrid worldGrid_;
    std::vector<std::uint64_t> maxActivations_;              // per story, per vehicle (max: unlimited)
    std::vector<std::size_t> pureStories_;                   // indices of the pure stories
    std::vector<std::vector<ConditionResult>> precomputed_;  // per pure story, per vehicle of the step
    std::vector<Condition*> conditions_;                     // every distinct node of every tree, for prepare/forget
    std::unordered_set<Condition*> knownConditions_;
    std::optional<double> neighbourRadius_;
    traffic::NeighbourGrid grid_;
    std::unordered_map<std::string, VehicleState> vehicles_;  // vehicles with state (node-stable)
    // The last pass's vehicles by snapshot index (ids ascending), carried over by matchStates().
    std::vector<std::string> stateIds_;
    std::vector<Row> rows_;
    std::vector<std::uint8_t> activeFlags_;  // rows_.size() × flagStride_: story active for the vehicle
    std::size_t flagStride_ = 0;
    std::vector<Row> rowScratch_;
    std::vector<std::uint8_t> flagScratch_;
    std::vector<std::string> leftSinceStep_;
    std::unique_ptr<traffic::VehicleRegistry> ownRegistry_;  // unless given one (useRegistry)
    traffic::VehicleRegistry* registry_;
    std::unique_ptr<traffic::TrafficQueries> queries_;
    double updateSeconds_ = 0;
    std::map<std::string, std::uint64_t, std::less<>> signalsByCause_;
    kernel::SimTime warmupEnd_;
    std::optional<traffic::Penetration> equippedOnly_;
    bool paintStories_ = false;
    std::vector<std::unique_ptr<Effect>> paints_;  // per story, made on first activation (paintStories)
    traffic::VehicleSnapshot equippedView_;        // the equipped vehicles of the step, with equippedOnly_
    std::vector<traffic::VehicleSnapshot::Index> equippedScratch_;
};

}  // namespace sbsim::storyboard
