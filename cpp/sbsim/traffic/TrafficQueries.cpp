#include "sbsim/traffic/TrafficQueries.h"

#include <libsumo/Simulation.h>
#include <libsumo/Vehicle.h>

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

}  // namespace sbsim::traffic
