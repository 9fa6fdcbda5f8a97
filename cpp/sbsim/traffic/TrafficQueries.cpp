#include "sbsim/traffic/TrafficQueries.h"

#include <libsumo/Lane.h>
#include <libsumo/Simulation.h>
#include <libsumo/TrafficLight.h>
#include <libsumo/Vehicle.h>

#include <algorithm>
#include <stdexcept>

namespace sbsim::traffic {

std::optional<TrafficQueries::Leader> SumoQueries::leader(const std::string& vehicle, double lookAhead) {
    const std::pair<std::string, double> found = libsumo::Vehicle::getLeader(vehicle, lookAhead);
    if (found.first.empty()) return std::nullopt;
    // getLeader measures from the ego's front bumper plus its minGap; the gap is bumper to bumper.
    return Leader{found.first, found.second + libsumo::Vehicle::getMinGap(vehicle)};
}

const std::vector<TrafficQueries::Collision>& SumoQueries::collisions(kernel::SimTime now) {
    if (collisionsAt_ != now) {
        collisions_.clear();
        for (const libsumo::TraCICollision& c : libsumo::Simulation::getCollisions())
            collisions_.push_back({c.collider, c.victim});
        collisionsAt_ = now;
    }
    return collisions_;
}

std::optional<TrafficQueries::SignalPassage> SumoQueries::signalPassage(const std::string& vehicle,
                                                                        const std::string& from,
                                                                        const std::string& to) {
    if (!signals_) signals_ = SignalLinks::ofLoadedSumo();
    if (!signals_->isApproach(from)) return std::nullopt;
    // SUMO moved a vehicle stuck for --time-to-teleport onto its next road: no driver passed a line.
    for (const auto& teleported :
         {libsumo::Simulation::getStartingTeleportIDList(), libsumo::Simulation::getEndingTeleportIDList()}) {
        if (std::find(teleported.begin(), teleported.end(), vehicle) != teleported.end()) return std::nullopt;
    }
    std::optional<SignalLinks::Link> link = signals_->passed(from, to);
    if (!link && !to.empty() && libsumo::Lane::getEdgeID(to) != libsumo::Lane::getEdgeID(from)) {
        // Past the junction's target lane within one step (a short edge, a long step): the route
        // says which edge followed the approach.
        const std::vector<std::string> route = libsumo::Vehicle::getRoute(vehicle);
        const auto at = std::find(route.begin(), route.end(), libsumo::Lane::getEdgeID(from));
        if (at != route.end() && at + 1 != route.end()) link = signals_->toward(from, *(at + 1));
    }
    if (!link) return std::nullopt;
    const std::string state = libsumo::TrafficLight::getRedYellowGreenState(link->signal);
    const auto index = static_cast<std::size_t>(link->index);
    return SignalPassage{*link, index < state.size() ? state[index] : 'O'};
}

double TrafficQueries::odometer(const std::string& /*vehicle*/) {
    throw std::logic_error("this TrafficQueries does not answer odometer()");
}

std::string TrafficQueries::signalState(const std::string& /*tls*/) {
    throw std::logic_error("this TrafficQueries does not answer signalState()");
}

double SumoQueries::odometer(const std::string& vehicle) { return libsumo::Vehicle::getDistance(vehicle); }

}  // namespace sbsim::traffic
