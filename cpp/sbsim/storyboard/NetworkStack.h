#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/LatestWins.h"
#include "sbsim/traffic/NetworkController.h"

namespace sbsim::storyboard {

/// The network's active world effects, composed so that the network always looks as if only the
/// active ones had ever acted (EffectStack's role for one vehicle):
/// - closed edges: an edge is closed while any closure names it. Its lanes' permissions are
///   recorded when the first closure arrives and restored exactly when the last one ends, in
///   whatever order they end. Vehicles that would drive onto a closed edge are re-routed around
///   it when it closes, and so are vehicles SUMO loads later (route files load vehicles ahead of
///   their departure) or inserts in the step that made them (a flow's). A vehicle already on a
///   closed edge drives off it. One that has not moved yet and cannot avoid the closure (its trip
///   starts or ends on a closed edge, or there is no way around) is removed, with a warning: SUMO
///   would stop the run with "has no valid route" when inserting it. A running one keeps its
///   route and waits at the closure (until it opens or SUMO teleports it), with a warning. While
///   any edge is closed SUMO's route checks are off (SUMO makes a flow's vehicle and inserts it in
///   one step, with no moment between to take it out): SUMO drops a vehicle whose first edge is
///   closed itself, and step() checks each inserted vehicle's route in the checks' place;
/// - held signals: per traffic light, the most recently activated state rules; the programme and
///   phase from before the first are set again after the last.
/// A command goes to SUMO only when an effective value changes.
class SBSIM_API NetworkStack {
public:
    using Token = std::uint64_t;
    using Warn = std::function<void(const std::string& message)>;

    explicit NetworkStack(traffic::NetworkController& network, Warn warn = {})
        : network_(&network), warn_(std::move(warn)) {}

    /// Throws std::invalid_argument, before changing anything, if an edge is not in the network.
    void pushClosure(Token token, const std::vector<std::string>& edges);
    /// Throws std::invalid_argument, before changing anything, for an unknown traffic light or a
    /// state whose length is not the light's number of signals.
    void pushSignalState(Token token, const std::string& tls, const std::string& state);
    /// Switches the light's programme to `phase` (its full duration, then on as programmed): every
    /// hold of the light ends first (its programme is set again; the holds' later removal does
    /// nothing). Throws std::invalid_argument, before changing anything, for an unknown light.
    void switchPhase(const std::string& tls, int phase);
    /// Removes the activation `token` from whichever domain holds it; unknown tokens are ignored.
    void remove(Token token);
    /// Removes vehicle `id` from the simulation now (a world effect's doing); one that had
    /// departed joins removedAfterInsertion(), so the vehicle pass leaves it alone this step.
    /// False if SUMO has no such vehicle (it left already).
    bool removeVehicle(const std::string& id);
    /// Called once per step, before world stories act: while edges are closed, steers the vehicles
    /// SUMO loaded or inserted in the step (and those that left a closed edge since) around them.
    /// Throws traffic::SumoError for a vehicle inserted with a route broken for another reason
    /// (SUMO's route checks, which would have stopped the run, are off while edges are closed).
    void step();

    bool closed(const std::string& edge) const { return closures_.contains(edge); }
    /// SUMO's route checks as they are when no edge is closed (the user's --ignore-route-errors).
    bool routeChecksOutsideClosures() const { return savedRouteChecks_.value_or(network_->routeChecks()); }
    std::set<std::string> closedEdges() const;
    std::optional<std::string> heldState(const std::string& tls) const;
    /// The vehicles the last step() removed after SUMO had inserted them (they are in that
    /// step's snapshot, but gone from SUMO), sorted.
    const std::vector<std::string>& removedAfterInsertion() const { return removedAfterInsertion_; }

private:
    struct Closure {
        std::vector<Token> tokens;
        std::vector<std::pair<std::string, traffic::LanePermissions>> lanes;  // recorded at closing
    };
    struct SignalHold {
        traffic::LatestWins<std::string> states;
        std::string program;
        int phase = 0;
    };

    /// Where a vehicle is when it is steered: loaded and waiting to depart; inserted by SUMO in
    /// the step that made it (a flow's vehicle), not moved yet; or on its way.
    enum class Phase { Waiting, Inserted, Running };

    /// Re-routes or removes the vehicle if its way on meets a closure; false if it does not.
    bool steer(const std::string& vehicle, Phase phase);
    /// Whether SUMO would find the vehicle a way from its route's first to its last edge were no
    /// edge closed.
    bool routableWithoutClosures(const std::string& vehicle);
    bool crossesClosure(const std::vector<std::string>& route, std::size_t from) const;
    void warn(const std::string& message) const {
        if (warn_) warn_(message);
    }

    traffic::NetworkController* network_;
    Warn warn_;
    std::map<std::string, Closure> closures_;    // by edge
    std::map<std::string, SignalHold> signals_;  // by traffic light
    std::set<std::string> onClosed_;             // were on a closed edge when it closed: steered once off it
    std::optional<bool> savedRouteChecks_;
    std::vector<std::string> removedAfterInsertion_;  // SUMO's route checks before the first closure (off during)
};

}  // namespace sbsim::storyboard
