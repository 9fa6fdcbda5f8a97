#include "sbsim/services/ca/RsuCaService.h"

#include "sbsim/facilities/Cam.h"
#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/ServicesConfig.h"

namespace sbsim::services {

SBSIM_REGISTER_SERVICE(RsuCaService);

void RsuCaService::initialize() { interval_ = spec().duration("generationInterval", 1.0); }

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
