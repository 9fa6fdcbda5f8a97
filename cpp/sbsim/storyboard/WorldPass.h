#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/EventLog.h"
#include "sbsim/storyboard/NetworkStack.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/WorldEffect.h"
#include "sbsim/traffic/NeighbourGrid.h"
#include "sbsim/traffic/NetworkController.h"
#include "sbsim/traffic/VehicleRegistry.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::storyboard {

/// The board's pass over the world stories, once per step, in registration order, before the
/// vehicles' pass: the network the step's vehicle stories act on is then the one the world stories
/// made for that step (a closure's re-routing is done before a vehicle story commands the
/// vehicle, a vehicle spawned at t is known to SUMO from t on). Their conditions see a world of one
/// row with the id "" (no SUMO vehicle has that id), so Hold and Rising keep their state for the
/// world apart from any vehicle's.
class SBSIM_API WorldPass {
public:
    /// Events go to `log` from now on (a log the board made when a criterion reads events).
    void setLog(EventLog* log) { log_ = log; }
    /// Effect activations take their tokens from `registry` (unique across everything that acts).
    WorldPass(traffic::VehicleRegistry& registry, EventLog* log);
    ~WorldPass();
    WorldPass(const WorldPass&) = delete;
    WorldPass& operator=(const WorldPass&) = delete;

    /// Replaces how world effects command the network (default: libsumo).
    void setNetworkController(std::unique_ptr<traffic::NetworkController> network);
    void addStory(Story& story);
    bool empty() const { return stories_.empty(); }

    /// Evaluates every world story at `now`; what an effect throws becomes a StoryError naming the
    /// story, the effect and the time.
    void run(kernel::SimTime now);

    /// Whether the world story `story` is active now.
    bool isActive(const Story& story) const;
    /// The network's composition of world effects (closed edges, held signals).
    const NetworkStack& network() const { return *networkStack_; }

private:
    class Scope;
    struct Entry {
        Story* story;
        bool active = false;
        std::vector<std::pair<WorldEffect*, NetworkStack::Token>> applied;  // non-empty iff active
    };

    void activate(Entry& entry);
    void deactivate(Entry& entry);

    traffic::VehicleRegistry& registry_;
    EventLog* log_;
    kernel::SimTime now_;
    std::vector<Entry> stories_;
    std::unique_ptr<traffic::NetworkController> network_;
    std::unique_ptr<NetworkStack> networkStack_;
    traffic::VehicleSnapshot worldSnapshot_;  // the world's one row, at the step's time
    traffic::NeighbourGrid worldGrid_;
};

}  // namespace sbsim::storyboard
