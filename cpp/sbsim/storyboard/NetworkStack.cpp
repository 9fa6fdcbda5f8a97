#include "sbsim/storyboard/NetworkStack.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::storyboard {

void NetworkStack::pushClosure(Token token, const std::vector<std::string>& edges) {
    for (const std::string& edge : edges) {
        if (!network_->hasEdge(edge)) throw std::invalid_argument(fmt::format("no edge '{}' in the network", edge));
    }
    if (closures_.empty()) {
        // SUMO makes a flow's vehicle and inserts it within one step: with its route checks on, one
        // whose trip the closure cut would stop the run before step() could take it out.
        savedRouteChecks_ = network_->routeChecks();
        network_->setRouteChecks(false);
    }
    bool newlyClosed = false;
    for (const std::string& edge : std::set<std::string>(edges.begin(), edges.end())) {
        auto [it, first] = closures_.try_emplace(edge);
        it->second.tokens.push_back(token);
        if (!first) continue;  // already closed: the first closure recorded the permissions
        for (const std::string& lane : network_->lanes(edge)) {
            it->second.lanes.emplace_back(lane, network_->permissions(lane));
            network_->closeLane(lane);
        }
        newlyClosed = true;
    }
    if (!newlyClosed) return;
    for (const std::string& vehicle : network_->knownVehicles()) {
        steer(vehicle, network_->hasDeparted(vehicle) ? Phase::Running : Phase::Waiting);
    }
}

void NetworkStack::pushSignalState(Token token, const std::string& tls, const std::string& state) {
    if (!network_->hasTrafficLight(tls)) {
        throw std::invalid_argument(fmt::format("no traffic light '{}' in the network", tls));
    }
    const std::string current = network_->signalState(tls);
    if (current.size() != state.size()) {
        throw std::invalid_argument(fmt::format("the state '{}' has {} signals, traffic light '{}' controls {}", state,
                                                state.size(), tls, current.size()));
    }
    SignalHold& hold = signals_[tls];
    if (hold.states.empty()) {
        hold.program = network_->program(tls);
        hold.phase = network_->phase(tls);
    }
    if (const auto v = hold.states.push(token, state, [&] { return current; })) network_->setSignalState(tls, *v);
}

void NetworkStack::switchPhase(const std::string& tls, int phase) {
    if (!network_->hasTrafficLight(tls)) {
        throw std::invalid_argument(fmt::format("no traffic light '{}' in the network", tls));
    }
    if (const auto it = signals_.find(tls); it != signals_.end()) {
        network_->setProgram(tls, it->second.program);
        signals_.erase(it);
    }
    network_->setPhase(tls, phase);
}

void NetworkStack::remove(Token token) {
    for (auto it = closures_.begin(); it != closures_.end();) {
        std::erase(it->second.tokens, token);
        if (!it->second.tokens.empty()) {
            ++it;
            continue;
        }
        for (const auto& [lane, recorded] : it->second.lanes) network_->setPermissions(lane, recorded);
        it = closures_.erase(it);
    }
    if (closures_.empty() && savedRouteChecks_) {
        network_->setRouteChecks(*savedRouteChecks_);
        savedRouteChecks_.reset();
    }
    for (auto it = signals_.begin(); it != signals_.end();) {
        SignalHold& hold = it->second;
        if (!hold.states.contains(token)) {
            ++it;
            continue;
        }
        const auto v = hold.states.remove(token);
        if (!hold.states.empty()) {
            if (v) network_->setSignalState(it->first, *v);
            ++it;
            continue;
        }
        // The programme takes over again, at the phase it was interrupted in.
        network_->setProgram(it->first, hold.program);
        network_->setPhase(it->first, hold.phase);
        it = signals_.erase(it);
    }
}

void NetworkStack::step() {
    removedAfterInsertion_.clear();
    if (closures_.empty()) {
        onClosed_.clear();
        return;
    }
    // Route files load vehicles ahead of their departure: they wait, and are steered now.
    for (const std::string& id : network_->loadedVehicles()) {
        if (!network_->hasVehicle(id)) {
            // Made and gone in one step: SUMO could not insert it and, its route checks off, dropped
            // it (its own warning, if SUMO's warnings are on, names the edge).
            warn(
                fmt::format("vehicle '{}' removed before it departed: SUMO dropped it, no lane of its first edge "
                            "letting it on (a closed edge, or one its class may never use)",
                            id));
        } else if (!network_->hasDeparted(id)) {
            steer(id, Phase::Waiting);
        }
    }
    // SUMO makes a flow's vehicle in the step it inserts it, and with its route checks off it
    // inserts whatever it could not route: on their first edge now, they are looked at before
    // they move. (Those whose first edge is closed SUMO dropped already, with its warning.)
    for (const std::string& id : network_->departedVehicles()) {
        if (!network_->hasVehicle(id)) continue;
        if (steer(id, Phase::Inserted) || network_->routeValid(id)) continue;
        // SUMO found no way for a trip whose route misses the closed edges: its only ways crossed
        // them. Any other broken route ends the run, as SUMO's own check would have.
        if (!network_->routedBySumo(id) || !routableWithoutClosures(id)) {
            throw traffic::SumoError(fmt::format("Vehicle '{}' has no valid route.", id));
        }
        const std::vector<std::string> route = network_->route(id);
        network_->removeVehicle(id);
        removedAfterInsertion_.push_back(id);
        warn(
            fmt::format("vehicle '{}' removed in the step SUMO made and inserted it, before it moved: its trip "
                        "from {} to {} cannot avoid the closed edges",
                        id, route.front(), route.back()));
    }
    std::sort(removedAfterInsertion_.begin(), removedAfterInsertion_.end());
    for (auto it = onClosed_.begin(); it != onClosed_.end();) {
        const std::string id = *it;
        it = onClosed_.erase(it);
        if (network_->hasVehicle(id)) steer(id, Phase::Running);  // back in the set while still on a closed edge
    }
}

std::set<std::string> NetworkStack::closedEdges() const {
    std::set<std::string> out;
    for (const auto& [edge, closure] : closures_) out.insert(edge);
    return out;
}

std::optional<std::string> NetworkStack::heldState(const std::string& tls) const {
    const auto it = signals_.find(tls);
    if (it == signals_.end()) return std::nullopt;
    return it->second.states.effective();
}

bool NetworkStack::routableWithoutClosures(const std::string& vehicle) {
    // The closed lanes open for the question only (between two steps: no vehicle moves meanwhile).
    for (const auto& [edge, closure] : closures_) {
        for (const auto& [lane, recorded] : closure.lanes) network_->setPermissions(lane, recorded);
    }
    const std::vector<std::string> route = network_->route(vehicle);
    const bool way =
        !route.empty() && !network_->findRoute(route.front(), route.back(), network_->vehicleType(vehicle)).empty();
    for (const auto& [edge, closure] : closures_) {
        for (const auto& [lane, recorded] : closure.lanes) network_->closeLane(lane);
    }
    return way;
}

bool NetworkStack::crossesClosure(const std::vector<std::string>& route, std::size_t from) const {
    return std::any_of(route.begin() + static_cast<std::ptrdiff_t>(std::min(from, route.size())), route.end(),
                       [this](const std::string& edge) { return closed(edge); });
}

bool NetworkStack::steer(const std::string& vehicle, Phase phase) {
    const std::vector<std::string> route = network_->route(vehicle);
    if (route.empty()) return false;
    std::size_t from = 0;
    if (phase == Phase::Running) {
        from =
            static_cast<std::size_t>(std::clamp(network_->routeIndex(vehicle), 0, static_cast<int>(route.size()) - 1));
        if (closed(route[from])) {
            onClosed_.insert(vehicle);  // it drives off; its way on is looked at once it has
            return true;
        }
        if (!crossesClosure(route, from + 1)) return false;
    } else if (!crossesClosure(route, 0)) {
        return false;
    }
    const std::string& start = route[from];
    const std::string& end = route.back();
    std::vector<std::string> around;
    if (!closed(start) && !closed(end)) around = network_->findRoute(start, end, network_->vehicleType(vehicle));
    if (around.empty() || crossesClosure(around, 0)) {
        if (phase == Phase::Waiting) {
            network_->removeVehicle(vehicle);
            warn(
                fmt::format("vehicle '{}' removed before it departed: its trip from {} to {} cannot avoid the closed "
                            "edges (SUMO would stop the run with 'no valid route' when inserting it)",
                            vehicle, start, end));
        } else if (phase == Phase::Inserted) {
            network_->removeVehicle(vehicle);
            removedAfterInsertion_.push_back(vehicle);
            warn(
                fmt::format("vehicle '{}' removed in the step SUMO made and inserted it, before it moved: its trip "
                            "from {} to {} cannot avoid the closed edges",
                            vehicle, start, end));
        } else {
            warn(
                fmt::format("vehicle '{}' cannot avoid the closed edges on its way to {}: it keeps its route and "
                            "waits at the closure",
                            vehicle, end));
        }
        return true;
    }
    network_->reroute(vehicle);
    return true;
}

bool NetworkStack::removeVehicle(const std::string& id) {
    if (!network_->hasVehicle(id)) return false;
    const bool departed = network_->hasDeparted(id);
    network_->removeVehicle(id);
    if (departed) {
        const auto at = std::lower_bound(removedAfterInsertion_.begin(), removedAfterInsertion_.end(), id);
        if (at == removedAfterInsertion_.end() || *at != id) removedAfterInsertion_.insert(at, id);
    }
    return true;
}

}  // namespace sbsim::storyboard
