#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "sbsim/facilities/ItsMessageHandler.h"
#include "sbsim/facilities/StationFacilities.h"
#include "sbsim/facilities/StationRegistry.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Module.h"
#include "sbsim/kernel/StudyParameters.h"
#include "sbsim/radio/Medium.h"
#include "sbsim/radio/V2xMessage.h"
#include "sbsim/services/ServiceVehicle.h"
#include "sbsim/traffic/StoryboardSignal.h"
#include "sbsim/traffic/VehicleController.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::services {

class Middleware;
struct ServiceSpec;

/// Base of per-vehicle V2X applications, in OMNeT++'s style: a kernel module with
/// initialize() when its vehicle departs, finish() when it arrives (or the run ends), its own
/// timers (scheduleAt / cancelEvent / handleMessage), plus the middleware's calls below.
///
///     class Beacon : public sbsim::services::Service {
///         void trigger() override { send(std::make_unique<BeaconMessage>()); }
///     };
///     SBSIM_REGISTER_SERVICE(Beacon);
///
/// CAMs and DENMs arrive at indicate() like any message; a service that also derives from
/// facilities::ItsMessageHandler gets them at indicateCam() / indicateDenm() too, after the
/// station's facilities took them in. (A mix-in rather than a base of Service, so that service
/// modules built against an older Service keep their layout.)
class SBSIM_API Service : public kernel::Module {
public:
    Service() : kernel::Module("service") {}

    /// Every middleware update interval (default 0.1 s), on the interval's grid.
    virtual void trigger() {}
    /// A storyboard SignalEffect fired for this vehicle (or for any, after listenToAllSignals()).
    virtual void receiveSignal(const traffic::StoryboardSignal& /*signal*/) {}
    /// A message another vehicle's service broadcast, arriving here.
    virtual void indicate(const radio::V2xMessage& /*message*/) {}

    const std::string& vehicleId() const;
    /// This service's entry of the services file.
    const ServiceSpec& spec() const;
    /// The station's id: its vehicle's, or the roadside unit's.
    const std::string& stationId() const { return vehicleId(); }

    /// Rethrows what this service's code threw as a ServiceError naming the service type, the
    /// vehicle and the time (a ServicesConfigError, a bad parameter, stays as it is).
    [[noreturn]] void failed() override;

protected:
    /// Commands and live queries for this service's vehicle; a max speed set here composes with
    /// the stories' caps (ServiceVehicle).
    ServiceVehicle& vehicle();
    /// The current step's snapshot of all vehicles (read-only).
    const traffic::VehicleSnapshot& snapshot() const;
    /// This vehicle's index in snapshot(), if it is running.
    std::optional<traffic::VehicleSnapshot::Index> selfIndex() const;

    /// Whether the station is a roadside unit: it has no vehicle to ask or command.
    bool roadsideUnit() const;
    /// Where the station is now (a vehicle: the current step's front bumper), SUMO network frame.
    Eigen::Vector2d position() const;
    /// What this station heard: its local dynamic map (CAMs) and DENM memory.
    const facilities::StationFacilities& facilities() const;
    const facilities::LocalDynamicMap& localDynamicMap() const { return facilities().ldm; }
    const facilities::DenmMemory& denmMemory() const { return facilities().denms; }
    /// Every station's facilities, and where DENM phase events are reported.
    facilities::StationRegistry& stations() const;
    /// The radio medium the station sends on (its DCC interval, if it models DCC).
    radio::Medium& medium() const;

    /// Broadcasts `message` to the services of every other vehicle in range (a geo-broadcast, such
    /// as a DENM, through the station's GeoNetworking router: forwarded through its area).
    void send(std::unique_ptr<radio::V2xMessage> message);
    /// From now on, also receive storyboard signals meant for other vehicles.
    void listenToAllSignals();

    /// Records a scalar of this service (OMNeT++'s recordScalar), typically once in finish(): a row
    /// (this vehicle, this service's type, `name`, now, `value`) of the run's statistics
    /// (--statistics) and a value of `name`'s aggregate in the summary. Throws
    /// std::invalid_argument for an empty name or a value that is not finite.
    void recordScalar(std::string_view name, double value);
    /// Records one value of the time series `name` at the current time (OMNeT++'s emit of a
    /// statistic): the same row as recordScalar, once per call.
    void emit(std::string_view name, double value);
    using kernel::Module::emit;  // the kernel's signals stay reachable

    /// A study parameter of the run (`--param NAME=VALUE`), or nothing; reading it counts as
    /// used. Lets a sweep vary a service's threshold or range without editing the services file.
    std::optional<kernel::StudyParameters::Value> studyParameter(const std::string& name) const;
    /// A parameter from the services file (an attribute of the <service> element).
    std::optional<std::string> parameter(const std::string& name) const;
    /// A numeric parameter, or `fallback` when absent; a malformed value is a configuration error.
    double numberParameter(const std::string& name, double fallback) const;

private:
    friend class Middleware;
    friend class DenmSender;  // sends, schedules and reports for the service that owns it
    Middleware* middleware_ = nullptr;
    const ServiceSpec* spec_ = nullptr;
};

}  // namespace sbsim::services
