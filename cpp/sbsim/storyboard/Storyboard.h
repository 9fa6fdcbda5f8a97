#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Module.h"
#include "sbsim/kernel/RandomStream.h"
#include "sbsim/kernel/Statistics.h"
#include "sbsim/storyboard/ActivationObserver.h"
#include "sbsim/storyboard/Criterion.h"
#include "sbsim/storyboard/EventLog.h"
#include "sbsim/storyboard/NetworkStack.h"
#include "sbsim/storyboard/StepNeighbours.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/VehiclePass.h"
#include "sbsim/storyboard/WorldPass.h"
#include "sbsim/traffic/NeighbourGrid.h"
#include "sbsim/traffic/NetworkController.h"
#include "sbsim/traffic/Penetration.h"
#include "sbsim/traffic/SnapshotColumns.h"
#include "sbsim/traffic/TrafficQueries.h"
#include "sbsim/traffic/VehicleRegistry.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::storyboard {

/// Evaluates the registered stories after every SUMO step (update()): first every active story of
/// every vehicle that left is deactivated with reason "vehicle_left" and its state dropped, then
/// the conditions prepare for the step, then the world stories act (WorldPass), then every
/// vehicle's stories (VehiclePass). The board owns the stories, their condition nodes and the
/// neighbour grid; the two passes act; each story counts what it did (Story::counters()).
class SBSIM_API Storyboard : public kernel::Module {
public:
    /// Vehicles are commanded through `registry`'s controllers and effect stacks, shared with the
    /// services; `log` (optional) receives the event lines. Random streams and the threads
    /// evaluating pure stories are the simulation's.
    explicit Storyboard(traffic::VehicleRegistry& registry, EventLog* log = nullptr);
    ~Storyboard() override;

    /// The snapshot values the registered stories read (none without stories).
    traffic::SnapshotColumns columns() const;
    /// Called with columns() whenever a registered story changes it (the SUMO bridge reads them).
    void onColumnsChanged(std::function<void(traffic::SnapshotColumns)> listener);
    /// Replaces how world effects command the network (default: libsumo).
    void setNetworkController(std::unique_ptr<traffic::NetworkController> network) {
        world_.setNetworkController(std::move(network));
    }
    /// Replaces what conditions ask of the traffic beyond the snapshot (default: libsumo).
    void setTrafficQueries(std::unique_ptr<traffic::TrafficQueries> queries) { queries_ = std::move(queries); }
    /// What the stations heard over V2X, for the V2X conditions (DenmCondition, CamCondition).
    void hearStations(std::shared_ptr<const facilities::StationRegistry> stations) { stations_ = std::move(stations); }
    /// Which vehicles carry V2X equipment (--penetration), for EquippedCondition and the criteria's
    /// equipped_only (default: everyone).
    void setPenetration(const traffic::Penetration& penetration) { penetration_ = penetration; }
    /// `observer` sees every activation of a story for a vehicle (sbsim --gui paints them).
    void observeActivations(ActivationObserver& observer) { vehicles_.observe(observer); }

    /// Artery's warm-up period, as scripts ask for it (getWarmupEndTime); it changes nothing else.
    void setWarmupEndTime(kernel::SimTime t) { warmupEnd_ = t; }
    kernel::SimTime warmupEndTime() const { return warmupEnd_; }
    /// Where scripts' board.record goes (the run's, owned by its Scenario).
    void setStatistics(kernel::Statistics& statistics) { statistics_ = &statistics; }
    /// Null if none was set.
    kernel::Statistics* statistics() const { return statistics_; }

    void registerStory(StoryPtr story);
    /// Adds a criterion: it observes every step after the stories and judges at the run's end.
    void registerCriterion(CriterionPtr criterion);
    const std::vector<CriterionPtr>& criteria() const { return criteria_; }
    /// Each criterion's verdict now (at the run's end: over the whole run), in registration order.
    std::vector<std::pair<std::string, CriterionVerdict>> verdicts() const;
    const std::vector<StoryPtr>& stories() const { return stories_; }
    /// Random stream k of the simulation (Artery scripts pass the generator index).
    std::shared_ptr<kernel::RandomStream> randomStream(unsigned k) { return simulation().randomStream(k); }

    /// One evaluation pass: first the vehicles in `left` (any order), then every vehicle of `snapshot`.
    void update(const traffic::VehicleSnapshot& snapshot, std::vector<std::string> left);

    bool isActive(const std::string& vehicle, const Story& story) const { return vehicles_.isActive(vehicle, story); }
    /// Whether the WorldStory `story` is active now.
    bool isActive(const Story& story) const { return world_.isActive(story); }
    /// The network's composition of world effects (closed edges, held signals).
    const NetworkStack& network() const { return world_.network(); }
    /// Wall-clock seconds spent in update() (a profiling figure for the summary).
    double updateSeconds() const { return updateSeconds_; }
    /// How many signals SignalEffects emitted, by cause (the summary's figures).
    const std::map<std::string, std::uint64_t, std::less<>>& signalsByCause() const {
        return vehicles_.signalsByCause();
    }
    /// Vehicles the board keeps state for (effect stacks, activations): never more than are running.
    std::size_t vehicleStates() const { return vehicles_.vehicleStates(); }
    /// The most vehicles any one condition keeps state for (Hold, Likelihood, Limit, ...).
    std::size_t maxConditionStates() const;

private:
    void collectConditions(Condition& root);

    EventLog* log_;
    std::ostream discarded_{nullptr};   // where ownLog_ writes (nowhere) besides the lines it keeps
    std::unique_ptr<EventLog> ownLog_;  // when no log was given and a criterion reads events
    kernel::SimTime now_;
    bool updated_ = false;  ///< a pass has run: now_ is a step's time
    std::vector<StoryPtr> stories_;
    std::unordered_set<std::string> storyNames_;
    std::vector<CriterionPtr> criteria_;
    std::vector<Condition*> conditions_;  // every distinct node of every tree, for prepare/forget
    std::unordered_set<Condition*> knownConditions_;
    /// The union of conditions_' columns, kept as nodes arrive: recomputing it per registered
    /// story made registering n stories quadratic (100,000 stories took 80x the time of 10,000).
    traffic::SnapshotColumns conditionColumns_;
    std::optional<double> neighbourRadius_;
    StepNeighbours grid_;  // built only in steps where a condition searches neighbours
    std::unique_ptr<traffic::TrafficQueries> queries_;
    std::shared_ptr<const facilities::StationRegistry> stations_;
    traffic::Penetration penetration_;
    std::function<void(traffic::SnapshotColumns)> columnsChanged_;
    WorldPass world_;
    VehiclePass vehicles_;
    double updateSeconds_ = 0;
    kernel::SimTime warmupEnd_;
    kernel::Statistics* statistics_ = nullptr;
};

}  // namespace sbsim::storyboard
