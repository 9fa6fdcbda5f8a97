#include "sbsim/services/ca/RsuCaService.h"

#include "sbsim/facilities/Cam.h"
#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/ServicesConfig.h"

namespace sbsim::services {

SBSIM_REGISTER_SERVICE(RsuCaService);

void RsuCaService::initialize() {
    const double seconds = numberParameter("generationInterval", 1.0);
    if (!(seconds > 0)) {
        throw ServicesConfigError(spec().source + ":" + std::to_string(spec().line) +
                                  ": parameter 'generationInterval' of service 'RsuCaService' must be > 0 s");
    }
    interval_ = kernel::SimTime::fromSeconds(seconds);
}

void RsuCaService::trigger() {
    const kernel::SimTime now = simTime();
    if (last_ && now - *last_ < interval_) return;
    last_ = now;
    facilities::CamContent cam;
    cam.station = stationId();
    cam.stationType = facilities::StationType::RoadSideUnit;
    cam.generationTime = now;
    cam.position = position();
    send(std::make_unique<facilities::Cam>(std::move(cam)));
    ++sent_;
}

}  // namespace sbsim::services
