#include "sbsim/traffic/NetworkIds.h"

#include <libsumo/Edge.h>
#include <libsumo/Lane.h>
#include <libsumo/TrafficLight.h>
#include <libsumo/VehicleType.h>

#include <vector>

namespace sbsim::traffic {

NetworkIds NetworkIds::ofLoadedSumo() {
    const auto toSet = [](const std::vector<std::string>& ids) { return Ids(ids.begin(), ids.end()); };
    NetworkIds out;
    out.edges_ = toSet(libsumo::Edge::getIDList());
    out.lanes_ = toSet(libsumo::Lane::getIDList());
    out.trafficLights_ = toSet(libsumo::TrafficLight::getIDList());
    out.vehicleTypes_ = toSet(libsumo::VehicleType::getIDList());
    return out;
}

}  // namespace sbsim::traffic
