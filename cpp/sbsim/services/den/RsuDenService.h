#pragma once

#include <Eigen/Core>
#include <optional>

#include "sbsim/facilities/ActionId.h"
#include "sbsim/facilities/Denm.h"
#include "sbsim/kernel/Message.h"
#include "sbsim/services/ServiceTraits.h"
#include "sbsim/services/den/DenService.h"

namespace sbsim::services {

/// A roadside unit that announces one configured event by DENM, as infrastructure does for road
/// works or a closed lane: from `from` on it sends the DENM and repeats it every `interval` as
/// geo-broadcast to a circle of `area` m around the event; at `until` it ends the event (a
/// cancellation DENM, receivers drop it). When the event outlives its validity, the unit renews it
/// (an update: detection and reference time now) so that receivers keep it. Runs no use cases.
///
///     <rsu id="rsu0" x="1200" y="0">
///       <service type="RsuDenService" cause="3" subcause="0" from="10" until="200" interval="1"
///                area="800" relevance="1000" validity="60" x="1250" y="0"/>
///     </rsu>
///
/// Attributes (times in s, distances in m): cause (required; e.g. 3 roadworks, 2 accident),
/// subcause (0), from (0: from the start), until (none: the run's end), interval (1),
/// validity (until − from, else 600), area (1,000), relevance (none), trafficClass (1), x and y:
/// the event's position (default the unit's).
class SBSIM_API RsuDenService : public DenService {
public:
    /// Its one event's DENMs; no use cases.
    static constexpr ServiceTraits kProvides{.sendsDenms = true};

    RsuDenService();
    ~RsuDenService() override;
    /// Its one event needs no vehicle: it is the roadside unit's DEN service.
    std::string_view whyVehicle() const override { return {}; }

    void initialize() override;
    void trigger() override {}
    void handleMessage(kernel::Message& msg) override;

    /// The event while it is announced.
    const std::optional<facilities::ActionId>& event() const { return event_; }

private:
    void start();
    void renew();

    std::optional<double> x_, y_;
    facilities::DenmContent denm_;  // the template: cause, area, ...
    kernel::SimTime from_, interval_, validity_;
    std::optional<kernel::SimTime> until_;
    std::optional<facilities::ActionId> event_;
    kernel::Message startTimer_{"rsu denm start"};
    kernel::Message renewTimer_{"rsu denm renewal"};
    kernel::Message endTimer_{"rsu denm end"};
};

}  // namespace sbsim::services
