#include "sbsim/traffic/SumoPois.h"

#include <libsumo/POI.h>
#include <libsumo/Simulation.h>

#include <algorithm>
#include <stdexcept>

namespace sbsim::traffic {

std::vector<SumoPois::Poi> SumoPois::all() {
    if (!libsumo::Simulation::isLoaded()) throw std::logic_error("SUMO POIs are known only once SUMO is loaded");
    std::vector<std::string> ids = libsumo::POI::getIDList();
    std::sort(ids.begin(), ids.end());
    std::vector<Poi> pois;
    pois.reserve(ids.size());
    for (std::string& id : ids) {
        const libsumo::TraCIPosition p = libsumo::POI::getPosition(id);
        std::string type = libsumo::POI::getType(id);
        pois.push_back({std::move(id), std::move(type), Eigen::Vector2d(p.x, p.y)});
    }
    return pois;
}

}  // namespace sbsim::traffic
