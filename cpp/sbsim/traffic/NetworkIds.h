#pragma once

#include <set>
#include <string>
#include <string_view>

#include "sbsim/kernel/Export.h"

namespace sbsim::traffic {

/// The ids of a loaded SUMO's edges (internal ones, ":J3_0", too), lanes, traffic lights and
/// vehicle types, asked of libsumo once: what `sbsim check` validates the ids stories name against.
class SBSIM_API NetworkIds {
public:
    /// Asks libsumo; call after SumoBridge::load. Vehicle types are those SUMO knows at that time
    /// (its defaults, additional files' and the route files' read so far).
    static NetworkIds ofLoadedSumo();

    bool hasEdge(std::string_view id) const { return edges_.contains(id); }
    bool hasLane(std::string_view id) const { return lanes_.contains(id); }
    bool hasTrafficLight(std::string_view id) const { return trafficLights_.contains(id); }
    bool hasVehicleType(std::string_view id) const { return vehicleTypes_.contains(id); }

private:
    using Ids = std::set<std::string, std::less<>>;
    Ids edges_;
    Ids lanes_;
    Ids trafficLights_;
    Ids vehicleTypes_;
};

}  // namespace sbsim::traffic
