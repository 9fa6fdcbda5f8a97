#include "sbsim/storyboard/NetworkStack.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

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
    if (closures_.empty()) {
        onClosed_.clear();
        return;
    }
    // Route files load vehicles ahead of their departure; SUMO makes a flow's vehicle (and a
    // trip's given with no time to spare) in the step it inserts it. Those whose first edge is
    // closed SUMO dropped already, with its warning; the others are on their first edge now.
    for (const std::string& id : network_->loadedVehicles()) {
        if (!network_->hasVehicle(id)) continue;
        steer(id, network_->hasDeparted(id) ? Phase::Inserted : Phase::Waiting);
    }
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

bool NetworkStack::crossesClosure(const std::vector<std::string>& route, std::size_t from) const {
    return std::any_of(route.begin() + static_cast<std::ptrdiff_t>(std::min(from, route.size())), route.end(),
                       [this](const std::string& edge) { return closed(edge); });
}

void NetworkStack::steer(const std::string& vehicle, Phase phase) {
    const std::vector<std::string> route = network_->route(vehicle);
    if (route.empty()) return;
    std::size_t from = 0;
    if (phase == Phase::Running) {
        from =
            static_cast<std::size_t>(std::clamp(network_->routeIndex(vehicle), 0, static_cast<int>(route.size()) - 1));
        if (closed(route[from])) {
            onClosed_.insert(vehicle);  // it drives off; its way on is looked at once it has
            return;
        }
        if (!crossesClosure(route, from + 1)) return;
    } else if (!crossesClosure(route, 0)) {
        return;
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
        return;
    }
    network_->reroute(vehicle);
}

}  // namespace sbsim::storyboard
