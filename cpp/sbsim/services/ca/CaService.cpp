#include "sbsim/services/ca/CaService.h"

#include <cmath>

#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/ServicesConfig.h"

namespace sbsim::services {

SBSIM_REGISTER_SERVICE(CaService);

void CaService::initialize() {
    CamRuleSettings settings;
    settings.minInterval = spec().duration("minInterval", 0.1);
    settings.maxInterval = spec().duration("maxInterval", 1.0);
    settings.headingDelta = numberParameter("headingDelta", settings.headingDelta);
    settings.positionDelta = numberParameter("positionDelta", settings.positionDelta);
    settings.speedDelta = numberParameter("speedDelta", settings.speedDelta);
    settings.fixedRate = spec().boolean("fixedRate", false);
    dcc_ = spec().boolean("withDccRestriction", true);
    rules_.emplace(settings);
}

void CaService::trigger() {
    const auto self = selfIndex();
    if (!self) return;
    const auto& snap = snapshot();
    const Eigen::Vector2d position = snap.positions().col(*self);
    const double heading = snap.angles()[*self];
    const kernel::SimTime now = simTime();
    double yawRate = 0;
    if (lastHeading_ && now > lastHeading_->first) {
        // Signed change in (-180, 180], clockwise positive as SUMO's angle.
        double change = std::fmod(heading - lastHeading_->second + 540.0, 360.0) - 180.0;
        yawRate = change / (now - lastHeading_->first).seconds();
    }
    lastHeading_ = {now, heading};

    const CamDynamics dynamics{position, snap.speeds()[*self], heading};
    const std::optional<kernel::SimTime> dcc = dcc_ ? medium().dccInterval(stationId()) : std::nullopt;
    if (rules_->check(now, dynamics, dcc) == CamGenerationRules::Reason::None) return;

    facilities::CamContent cam;
    cam.station = stationId();
    cam.stationType = facilities::StationType::PassengerCar;
    cam.generationTime = now;
    cam.position = position;
    cam.speed = dynamics.speed;
    cam.heading = heading;
    cam.acceleration = snap.accelerations()[*self];
    cam.length = snap.lengths()[*self];
    cam.width = snap.widths()[*self];
    cam.yawRate = yawRate;
    if (!lastLowFrequency_ || now - *lastLowFrequency_ >= kLowFrequencyInterval) {
        facilities::CamLowFrequency low;
        low.pathHistory.assign(pathHistory_.begin(), pathHistory_.end());
        cam.lowFrequency = std::move(low);
        lastLowFrequency_ = now;
    }
    pathHistory_.push_front(position);
    if (pathHistory_.size() > facilities::CamLowFrequency::kPathHistoryLength) pathHistory_.pop_back();
    send(std::make_unique<facilities::Cam>(std::move(cam)));
    ++sent_;
}

}  // namespace sbsim::services
