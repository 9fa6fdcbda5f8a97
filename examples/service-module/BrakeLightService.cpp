#include "BrakeLightService.h"

#include <sbsim/services/ServiceRegistry.h>

namespace example {

SBSIM_REGISTER_SERVICE(BrakeLightService);

void BrakeLightService::initialize() {
    threshold_ = numberParameter("threshold", threshold_);
    reactDistance_ = numberParameter("react-distance", reactDistance_);
    cautionSpeed_ = numberParameter("caution-speed", cautionSpeed_);
    cautionTime_ = numberParameter("caution-time", cautionTime_);
}

void BrakeLightService::trigger() {
    const auto self = selfIndex();
    if (!self) return;
    const double acceleration = snapshot().accelerations()[*self];
    if (acceleration < -threshold_) {
        send(std::make_unique<BrakeLightMessage>(-acceleration));
    }
}

void BrakeLightService::indicate(const sbsim::radio::V2xMessage& message) {
    if (dynamic_cast<const BrakeLightMessage*>(&message) == nullptr || cautionOver_.isScheduled()) return;
    const auto self = selfIndex();
    const auto sender = snapshot().indexOf(message.sender());
    if (!self || !sender) return;
    const double distance = (snapshot().positions().col(*self) - snapshot().positions().col(*sender)).norm();
    if (distance > reactDistance_) return;
    vehicle().setMaxSpeed(cautionSpeed_);  // composes with the stories' caps
    scheduleAfter(sbsim::kernel::SimTime::fromSeconds(cautionTime_), cautionOver_);
}

void BrakeLightService::handleMessage(sbsim::kernel::Message& msg) {
    if (&msg == &cautionOver_) vehicle().endMaxSpeed();  // whatever rules without this cap comes back
}

}  // namespace example
