#pragma once

#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::traffic {

class SumoBridge;

/// Which vehicle classes a lane lets on, as SUMO reports them (libsumo Lane::getAllowed and
/// getDisallowed: each is the other's complement).
struct LanePermissions {
    std::vector<std::string> allowed;
    std::vector<std::string> disallowed;
    bool operator==(const LanePermissions&) const = default;
};

/// What one vehicle added by a story is made of; depart fields are SUMO's strings ("first",
/// "base", "0" are SUMO's defaults; numbers or SUMO's keywords such as "best", "random", "max").
struct VehicleSpawn {
    std::string id;
    std::string routeId;
    std::string typeId = "DEFAULT_VEHTYPE";
    std::string departLane = "first";
    std::string departPos = "base";
    std::string departSpeed = "0";
};

/// Commands and live queries on the network as a whole (lanes, routes, traffic lights, the set of
/// vehicles), forwarded to libsumo, as VehicleController is for one vehicle. World effects act on
/// SUMO only through this class. Virtual so that unit tests can stand a model network in.
class SBSIM_API NetworkController {
public:
    /// `sumo`, if given, hears of each vehicle removeVehicle() takes out (libsumo forgets such an
    /// arrival when the next step begins, so the bridge is told rather than asking every step).
    explicit NetworkController(SumoBridge* sumo = nullptr) : sumo_(sumo) {}
    virtual ~NetworkController() = default;

    virtual bool hasEdge(const std::string& edge) const;
    /// The edge's lane ids ("<edge>_<index>").
    virtual std::vector<std::string> lanes(const std::string& edge) const;
    virtual LanePermissions permissions(const std::string& lane) const;
    /// Sets what `recorded` says (as permissions() gave it), exactly.
    virtual void setPermissions(const std::string& lane, const LanePermissions& recorded);
    /// Lets no vehicle class onto the lane.
    virtual void closeLane(const std::string& lane);
    /// SUMO's route checks (see SumoRouteChecks.h): on, a vehicle SUMO cannot insert or route stops
    /// the run; off, SUMO drops or inserts it with a warning.
    virtual bool routeChecks() const;
    virtual void setRouteChecks(bool on);

    /// Every vehicle SUMO knows: running, teleporting, or loaded and waiting to depart (route
    /// files load vehicles ahead of their departure; libsumo Vehicle::getLoadedIDList).
    virtual std::vector<std::string> knownVehicles() const;
    /// The vehicles SUMO loaded in the last step (libsumo Simulation::getLoadedIDList).
    virtual std::vector<std::string> loadedVehicles() const;
    /// The vehicles SUMO inserted in the last step (libsumo Simulation::getDepartedIDList).
    virtual std::vector<std::string> departedVehicles() const;
    /// Whether SUMO finds the vehicle's route connected for its class (libsumo Vehicle::isRouteValid).
    virtual bool routeValid(const std::string& vehicle) const;
    /// Whether SUMO routes the vehicle itself (it has a rerouting device: a trip or a flow given
    /// from/to, which SUMO routes when inserting it).
    virtual bool routedBySumo(const std::string& vehicle) const;
    virtual bool hasVehicle(const std::string& id) const;
    virtual bool hasDeparted(const std::string& id) const;
    virtual std::vector<std::string> route(const std::string& vehicle) const;
    /// The index of the vehicle's edge in its route (-1 before it departs).
    virtual int routeIndex(const std::string& vehicle) const;
    virtual std::string vehicleType(const std::string& vehicle) const;
    /// The fastest route from `from` to `to` for `typeId` with the lanes' current permissions; empty if none.
    virtual std::vector<std::string> findRoute(const std::string& from, const std::string& to,
                                               const std::string& typeId) const;
    /// Re-routes the vehicle by travel time (libsumo Vehicle::rerouteTraveltime).
    virtual void reroute(const std::string& vehicle);
    virtual void removeVehicle(const std::string& vehicle);
    virtual bool hasRoute(const std::string& routeId) const;
    virtual void addRoute(const std::string& routeId, const std::vector<std::string>& edges);
    /// Adds a vehicle that departs at the next step.
    virtual void addVehicle(const VehicleSpawn& spawn);

    virtual bool hasTrafficLight(const std::string& tls) const;
    /// One letter per controlled link (libsumo TrafficLight::getRedYellowGreenState).
    virtual std::string signalState(const std::string& tls) const;
    virtual std::string program(const std::string& tls) const;
    virtual int phase(const std::string& tls) const;
    /// Holds the state until setProgram() (SUMO switches the light to its "online" programme).
    virtual void setSignalState(const std::string& tls, const std::string& state);
    virtual void setProgram(const std::string& tls, const std::string& programId);
    virtual void setPhase(const std::string& tls, int phase);

private:
    SumoBridge* sumo_;
};

}  // namespace sbsim::traffic
