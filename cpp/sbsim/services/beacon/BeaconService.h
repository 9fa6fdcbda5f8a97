#pragma once

#include "sbsim/kernel/Message.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/services/IndicatedTypes.h"
#include "sbsim/services/Service.h"
#include "sbsim/services/TriggerFree.h"

namespace sbsim::services {

/// Broadcasts a BeaconMessage of `bytes` bytes (default 190) every `interval` seconds (default
/// 0.1), as the fixed-rate beacons of Sepulcre et al.'s 802.11p evaluation. The first one goes at
/// a random phase in [0, interval) after the vehicle departs, drawn per vehicle from the seed, so
/// vehicles departing together do not send in lockstep. Its trigger() does nothing (TriggerFree).
///
///     <service type="Beacon" interval="0.1" bytes="190"/>
class BeaconService : public Service, public IndicatedTypes, public TriggerFree {
public:
    void initialize() override;
    /// None: it only sends (others' beacons need not visit the station).
    std::vector<std::string> indicatedTypes() const override { return {}; }
    void handleMessage(kernel::Message& msg) override;

private:
    kernel::SimTime interval_;
    std::size_t bytes_ = 190;
    kernel::Message timer_{"beacon"};
};

}  // namespace sbsim::services
