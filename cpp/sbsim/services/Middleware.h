#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include <Eigen/Core>
#include <optional>

#include "sbsim/facilities/StationFacilities.h"
#include "sbsim/facilities/StationRegistry.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Module.h"
#include "sbsim/radio/Receiver.h"
#include "sbsim/radio/StationIds.h"
#include "sbsim/radio/geonet/Router.h"
#include "sbsim/services/Service.h"
#include "sbsim/services/ServiceVehicle.h"
#include "sbsim/traffic/VehicleRegistry.h"

namespace sbsim::facilities {
class ItsMessage;
class ItsMessageHandler;
}  // namespace sbsim::facilities

namespace sbsim::services {

class ServiceManager;

/// One vehicle's middleware: created when the vehicle departs, it hosts the vehicle's services
/// (which the simulation owns, as modules) and hands them triggers, storyboard signals and incoming
/// V2X messages. Each station runs on its own clock, as Artery's middleware does "to avoid
/// unrealistic node synchronization": its first trigger comes a uniform phase in (0, interval]
/// after it departed (clockPhase()), then one every interval. Removed, services first, when the
/// vehicle arrives. It is the station's network and facilities layers too: a geo-broadcast message
/// whose destination area does not hold the station goes no further, and CAMs and DENMs go into the
/// station's LDM and DENM memory before its services see them; expired entries are dropped before
/// every trigger. A station all of whose services are TriggerFree needs its clock only for that
/// expiry: its clock stops while its facilities hold nothing and starts again, on the same grid,
/// when something is stored (see wake()). Its GeoNetworking router (radio::geonet::Router) forwards geo-broadcasts: the
/// contention timers are this module's self-messages, the neighbours for greedy forwarding those
/// of its LDM.
class SBSIM_API Middleware : public kernel::Module, public radio::Receiver {
public:
    Middleware(ServiceManager& manager, std::string vehicleId);

    const std::string& vehicleId() const { return vehicleId_; }
    /// What `service` (hosted here) commands the vehicle through.
    ServiceVehicle& vehicleOf(const Service& service);
    ServiceManager& manager() const { return manager_; }
    const std::vector<Service*>& services() const { return services_; }
    /// Where the station is: a roadside unit's fixed position, else its vehicle's in the current
    /// snapshot (the origin if it is not in it).
    Eigen::Vector2d position() const;
    /// The vehicle's index in the current snapshot, if it is in it (none for a roadside unit).
    /// Remembered from the last call and checked by one id comparison: a vehicle keeps its index
    /// while no other departs or arrives, so the binary search runs about once per step.
    std::optional<traffic::VehicleSnapshot::Index> selfIndex() const;
    /// The station's index for the run (facilities::StationRegistry, radio::StationIds).
    facilities::StationRegistry::Index stationIndex() const { return station_; }
    /// Makes this a stationary station (a roadside unit) at `position`.
    void setFixedPosition(const Eigen::Vector2d& position) { fixedPosition_ = position; }
    /// Whether this is a stationary station (a roadside unit), which has no vehicle.
    bool stationary() const { return fixedPosition_.has_value(); }
    /// This station's facilities (in the manager's station registry).
    facilities::StationFacilities& facilities() const;

    /// Hosts `service` (already owned by the simulation) with its configuration.
    void host(Service& service, const ServiceSpec& spec);
    /// Triggers the services now (the station's own clock calls it every interval).
    void trigger();
    /// The delay from departure to the first trigger: uniform in (0, `interval`], a pure function of
    /// (`seed`, `station`) (a counter-based draw), so it depends neither on the order stations
    /// depart in nor on the thread count.
    static kernel::SimTime clockPhase(std::uint64_t seed, std::string_view station, kernel::SimTime interval);
    void signal(const traffic::StoryboardSignal& signal);

    void initialize() override;
    /// A V2X message reached the station: through its router and the facilities to the services.
    void receive(const radio::V2xMessage& message) override;
    /// Sends `message` from this station: through its router to the medium.
    void send(std::unique_ptr<radio::V2xMessage> message);
    /// The contention-based forwarding timer.
    void handleMessage(kernel::Message& msg) override;
    const radio::geonet::Router& router() const { return router_; }

private:
    /// `message` as an ITS message, or null. A dynamic_cast that fails walks the hierarchy
    /// comparing type names (an eighth of the disc model's time at 23 M receptions): the answer
    /// depends only on the message's dynamic type, so it is remembered per type.
    const facilities::ItsMessage* itsPart(const radio::V2xMessage& message);
    /// The message types its services' indicate() take (IndicatedTypes), or none if one takes every type.
    std::optional<std::vector<std::string>> indicatedTypes() const;
    /// Whether service `service` (by place) takes messages of `type` at indicate().
    bool takes(std::size_t service, std::string_view type) const;
    /// The stations of its LDM, alive now, at their last CAM's position.
    std::vector<radio::geonet::Neighbour> neighbours() const;
    /// The forwarding timer at the router's next timeout (or off).
    void scheduleForwarding();
    /// Hands `message` to the medium as this station's (its index looked up at the first send).
    void broadcast(std::unique_ptr<radio::V2xMessage> message);
    /// The clock of a station whose services are all TriggerFree, stopped while its facilities were
    /// empty: started at the next instant of its grid after now. The triggers it skipped would have
    /// dropped nothing (there was nothing) and what was just stored expires after now.
    void wake();

    ServiceManager& manager_;
    std::string vehicleId_;
    facilities::StationRegistry::Index station_;
    // The medium's index of this station, from its first send on: the same index the medium's
    // stamp would have interned then (so the run's indices do not change), without a lookup per frame.
    std::optional<radio::StationIds::Index> radioIndex_;
    mutable traffic::VehicleSnapshot::Index selfHint_ = 0;        // where the vehicle was last found
    std::shared_ptr<traffic::VehicleRegistry::Vehicle> vehicle_;  // the storyboard's as well
    std::vector<Service*> services_;
    std::vector<std::unique_ptr<ServiceVehicle>> vehicles_;       // per service, as services_
    std::vector<facilities::ItsMessageHandler*> handlers_;        // per service, as services_; null: none
    std::vector<std::optional<std::vector<std::string>>> taken_;  // per service: the types indicate() takes; none: all
    const std::type_info* itsType_ = nullptr;                     // the last type found to be ITS
    const std::type_info* otherType_ = nullptr;                   // the last type found not to be
    bool triggered_ = false;        // some service is not TriggerFree: the clock never stops
    kernel::SimTime firstTrigger_;  // the clock's grid: firstTrigger_ + k * interval
    kernel::Message triggerTimer_{"middleware trigger"};
    std::optional<Eigen::Vector2d> fixedPosition_;
    radio::geonet::Router router_;
    kernel::Message forwardTimer_{"geonet forwarding"};
};

}  // namespace sbsim::services
