#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "sbsim/facilities/ActionId.h"
#include "sbsim/facilities/Denm.h"
#include "sbsim/kernel/Message.h"
#include "sbsim/services/NeedsVehicle.h"
#include "sbsim/services/Service.h"
#include "sbsim/services/ServiceTraits.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/services/den/DenmSender.h"
#include "sbsim/services/den/Repetition.h"
#include "sbsim/services/den/UseCase.h"

namespace sbsim::services {

/// ETSI's DEN basic service (EN 302 637-3) as Artery's DenService: it runs the use cases its
/// configuration lists (ServiceSpec::useCases, filtered per vehicle), checks them every trigger,
/// passes them storyboard signals and received DENMs, and sends their DENMs as geo-broadcast with
/// repetition. Unlike Artery it ends events: terminate() stops the repetition and sends a
/// cancellation DENM, which makes receivers drop the event. Reports "new" and "terminate" DENM
/// phases of its own events to the station registry's sink.
class SBSIM_API DenService : public Service, public facilities::ItsMessageHandler, public NeedsVehicle {
public:
    /// Its use cases send DENMs, and it reads the services file's use-case list.
    static constexpr ServiceTraits kProvides{.sendsDenms = true, .runsUseCases = true};

    DenService();
    ~DenService() override;
    std::string_view whyVehicle() const override {
        return "its use cases watch its vehicle (a unit announces an event with RsuDenService)";
    }

    void initialize() override;
    void trigger() override;
    void receiveSignal(const traffic::StoryboardSignal& signal) override;
    void indicateDenm(const facilities::Denm& denm) override;
    void handleMessage(kernel::Message& msg) override;

    /// The next action id of this station (sequence numbers from 1).
    facilities::ActionId requestActionId() { return sender_.requestActionId(); }
    /// Sends `denm` now and, with `repetition`, again every interval (the same content) until the
    /// duration passed or the event is terminated.
    void sendDenm(const facilities::DenmContent& denm, std::optional<Repetition> repetition = std::nullopt) {
        sender_.send(denm, repetition);
    }
    /// Ends this station's event `action`: no more repetitions, one cancellation DENM (reference
    /// time now) to the same area. Nothing if the event is not this station's or already ended.
    void terminate(const facilities::ActionId& action) { (void)sender_.terminate(action); }
    /// Whether `action` is one of this station's events still being repeated.
    bool repeating(const facilities::ActionId& action) const { return sender_.repeating(action); }

    kernel::SimTime now() const { return simTime(); }
    Eigen::Vector2d stationPosition() const { return position(); }
    double stationSpeed() const;
    double stationAcceleration() const;
    double stationHeading() const;
    const facilities::DenmMemory& memory() const { return denmMemory(); }
    const facilities::LocalDynamicMap& ldm() const { return localDynamicMap(); }
    const std::vector<std::unique_ptr<UseCase>>& useCases() const { return useCases_; }
    std::size_t denmsSent() const { return sender_.sent(); }

private:
    std::vector<std::unique_ptr<UseCase>> useCases_;
    DenmSender sender_{*this};              // the station's events: action ids, repetition, cancellation
    std::vector<ServiceSpec> allUseCases_;  // when the configuration lists none: every use case
};

}  // namespace sbsim::services
