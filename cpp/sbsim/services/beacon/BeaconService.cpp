#include "sbsim/services/beacon/BeaconService.h"

#include <cmath>
#include <memory>

#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/CounterRandom.h"
#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/services/beacon/BeaconMessage.h"

namespace sbsim::services {

SBSIM_REGISTER_SERVICE_AS(BeaconService, "Beacon");

void BeaconService::initialize() {
    interval_ = spec().duration("interval", 0.1);
    const double bytes = numberParameter("bytes", 190);
    if (!(bytes >= 1 && bytes <= 2304) || bytes != std::floor(bytes))
        throw ServicesConfigError("Beacon: bytes must be a whole number from 1 to 2304");
    bytes_ = static_cast<std::size_t>(bytes);
    radio::CounterRandom random(simulation().seed(), radio::CounterRandom::keyOf(vehicleId()), 0, 0,
                                radio::DrawPurpose::Start);
    const auto phase = static_cast<kernel::SimTime::rep>(random.uniform01() * static_cast<double>(interval_.raw()));
    scheduleAfter(kernel::SimTime::fromNanoseconds(phase), timer_);
}

void BeaconService::handleMessage(kernel::Message& msg) {
    if (&msg != &timer_) return Service::handleMessage(msg);
    send(std::make_unique<BeaconMessage>(bytes_));
    scheduleAfter(interval_, timer_);
}

}  // namespace sbsim::services
