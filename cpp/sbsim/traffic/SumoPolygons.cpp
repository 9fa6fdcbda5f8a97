#include "sbsim/traffic/SumoPolygons.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <libsumo/Polygon.h>
#include <libsumo/Simulation.h>

#include <algorithm>
#include <stdexcept>

namespace sbsim::traffic {

namespace {
void requireLoaded() {
    if (!libsumo::Simulation::isLoaded()) throw std::logic_error("SUMO polygons are known only once SUMO is loaded");
}
}  // namespace

std::vector<std::string> SumoPolygons::ids() {
    requireLoaded();
    std::vector<std::string> ids = libsumo::Polygon::getIDList();
    std::sort(ids.begin(), ids.end());
    return ids;
}

std::vector<Eigen::Vector2d> SumoPolygons::shape(const std::string& id) {
    // Looked up among the ids first: libsumo's own error for an unknown id names nothing else.
    const std::vector<std::string> known = ids();
    if (!std::binary_search(known.begin(), known.end(), id)) throw std::invalid_argument(unknownMessage(id, known));
    std::vector<Eigen::Vector2d> points;
    for (const libsumo::TraCIPosition& p : libsumo::Polygon::getShape(id).value) points.emplace_back(p.x, p.y);
    return points;
}

std::vector<SumoPolygons::Polygon> SumoPolygons::all() {
    std::vector<Polygon> polygons;
    for (std::string& id : ids()) {
        Polygon p{id, libsumo::Polygon::getType(id), {}};
        for (const libsumo::TraCIPosition& q : libsumo::Polygon::getShape(id).value) p.shape.emplace_back(q.x, q.y);
        polygons.push_back(std::move(p));
    }
    return polygons;
}

std::string SumoPolygons::unknownMessage(const std::string& id, const std::vector<std::string>& known) {
    if (known.empty()) {
        return fmt::format(
            "SUMO has no polygon '{}' (it loaded none: polygons come from <poly> elements in the "
            "sumocfg's additional-files)",
            id);
    }
    if (known.size() <= kNamedIds)
        return fmt::format("SUMO has no polygon '{}' (it has: {})", id, fmt::join(known, ", "));
    const std::vector<std::string> named(known.begin(), known.begin() + kNamedIds);
    return fmt::format("SUMO has no polygon '{}' (it has {}: {}, ...)", id, known.size(), fmt::join(named, ", "));
}

}  // namespace sbsim::traffic
