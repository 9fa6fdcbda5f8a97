#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "sbsim/facilities/StationRegistry.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Module.h"
#include "sbsim/kernel/Statistics.h"
#include "sbsim/radio/Medium.h"
#include "sbsim/radio/geonet/Router.h"
#include "sbsim/services/Middleware.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/traffic/Penetration.h"
#include "sbsim/traffic/SnapshotColumns.h"
#include "sbsim/traffic/SumoPois.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::services {

/// Gives each departing vehicle a middleware with the services its filters select, removes them
/// when it arrives, and routes storyboard signals to the ego vehicle's
/// services (and to services listening to all). Attach it to the SUMO bridge. The services
/// file's roadside units are made at initialize(): a middleware at a fixed position each, a
/// stationary station of the medium. Every middleware triggers its services on its own clock
/// (Middleware::clockPhase), every interval().
class SBSIM_API ServiceManager : public kernel::Module, private kernel::Listener {
public:
    /// Vehicles are commanded through `registry`, shared with the storyboard; `snapshot` is the
    /// SUMO bridge's. Throws std::out_of_range if the configuration names a service type nobody
    /// registered.
    ServiceManager(ServicesConfig config, kernel::SimTime interval, const traffic::VehicleSnapshot& snapshot,
                   traffic::VehicleRegistry& registry);
    ~ServiceManager() override;

    /// Listen to vehicles departing and arriving: `sumo` emits traffic::SumoBridge's departed and
    /// arrived signals (the bridge, or a stand-in).
    void attach(kernel::Module& sumo);
    /// The snapshot values services may read: any (tell the SUMO bridge).
    static traffic::SnapshotColumns columns() { return traffic::SnapshotColumns::all(); }
    traffic::VehicleRegistry& registry() const { return *registry_; }
    /// The medium the stations send on; every station's facilities take its ITS messages (CAMs,
    /// DENMs) whatever its services take (Medium::setLayersTake). The medium's directory must be
    /// this manager's middlewareOf(): the manager reports each station's change to it.
    void setMedium(radio::Medium& medium);
    bool hasMedium() const { return medium_ != nullptr; }
    /// How the stations' GeoNetworking routers forward geo-broadcasts (default: CBF and greedy
    /// forwarding, hop limit 10), for the middlewares made from now on.
    void setGeoNetworking(const radio::geonet::RouterSettings& settings) { geonet_ = settings; }
    const radio::geonet::RouterSettings& geoNetworking() const { return geonet_; }
    /// The stations' facilities (LDM, DENM memory), shared with the storyboard's V2X conditions
    /// (default: a registry of the manager's own). A station's entry goes when it leaves.
    void useStations(std::shared_ptr<facilities::StationRegistry> stations) { stations_ = std::move(stations); }
    facilities::StationRegistry& stations() const { return *stations_; }
    /// Where the services' recordScalar and emit go (the run's, owned by its Scenario).
    void setStatistics(kernel::Statistics& statistics) { statistics_ = &statistics; }
    /// Throws std::logic_error if none was set.
    kernel::Statistics& statistics() const;
    /// Which vehicles are equipped (--penetration); by default all. Unequipped vehicles get only
    /// the services whose filters ask for them (<equipped match="inverse"/> or "any").
    void setPenetration(const traffic::Penetration& penetration) { penetration_ = penetration; }

    /// Where roadside units with a `poiType` find their POIs (default: the loaded SUMO's).
    void setPoiSource(std::function<std::vector<traffic::SumoPois::Poi>()> source) { pois_ = std::move(source); }
    /// The roadside units made so far (at initialize()).
    std::size_t roadsideUnits() const { return roadsideUnits_.size(); }

    kernel::SimTime interval() const { return interval_; }
    const traffic::VehicleSnapshot& snapshot() const { return snapshot_; }
    radio::Medium& medium() const;
    Middleware* middlewareOf(const std::string& vehicleId) const;
    void listenToAllSignals(Service& service);
    std::size_t servicesCreated() const { return servicesCreated_; }
    /// Storyboard signals fired for a vehicle that has no services (the first is warned of).
    std::size_t signalsWithoutServices() const { return signalsWithoutServices_; }
    /// Vehicles with a middleware now (each running vehicle its filters selected; roadside units
    /// not counted).
    std::size_t middlewares() const { return middlewares_.size() - roadsideUnits_.size(); }

    void initialize() override;

private:
    void receiveSignal(kernel::Module& source, kernel::SignalId id, std::string_view value) override;
    void receiveSignal(kernel::Module& source, kernel::SignalId id, const kernel::Object& value) override;
    void depart(const std::string& id);
    void makeRoadsideUnits();
    void makeRoadsideUnit(const RoadsideUnitSpec& spec, const std::string& id, const Eigen::Vector2d& position);
    void arrive(const std::string& id);

    ServicesConfig config_;
    kernel::SimTime interval_;
    const traffic::VehicleSnapshot& snapshot_;
    radio::Medium* medium_ = nullptr;
    radio::geonet::RouterSettings geonet_;
    kernel::Statistics* statistics_ = nullptr;
    traffic::Penetration penetration_;
    std::unordered_map<std::string, Middleware*> middlewares_;
    std::vector<Middleware*> roadsideUnits_;  // in the services file's order
    std::unordered_map<std::string, const RoadsideUnitSpec*> roadsideUnitIds_;
    std::function<std::vector<traffic::SumoPois::Poi>()> pois_ = &traffic::SumoPois::all;
    std::vector<Service*> allSignals_;
    std::size_t servicesCreated_ = 0;
    std::size_t signalsWithoutServices_ = 0;
    traffic::VehicleRegistry* registry_;
    std::shared_ptr<facilities::StationRegistry> stations_ = std::make_shared<facilities::StationRegistry>();
};

}  // namespace sbsim::services
