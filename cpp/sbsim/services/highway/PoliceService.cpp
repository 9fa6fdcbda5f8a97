#include "sbsim/services/highway/PoliceService.h"

#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/highway/ClearLaneMessage.h"

namespace sbsim::services {

SBSIM_REGISTER_SERVICE(PoliceService);
SBSIM_REGISTER_SERVICE(PoliceServiceStoryboard);

void PoliceService::trigger() {
    if (!broadcasting()) return;
    const auto self = selfIndex();
    if (!self) return;
    const std::string& lane = snapshot().laneId(*self);
    // SUMO lane ids are "<road>_<index>".
    const auto underscore = lane.rfind('_');
    const int index = underscore == std::string::npos ? 0 : std::stoi(lane.substr(underscore + 1));
    send(std::make_unique<ClearLaneMessage>(snapshot().roadId(*self), index));
}

void PoliceServiceStoryboard::initialize() { cause_ = parameter("cause").value_or("siren on"); }

void PoliceServiceStoryboard::receiveSignal(const traffic::StoryboardSignal& signal) {
    if (signal.ego == vehicleId() && signal.cause == cause_) sirenOn_ = true;
}

}  // namespace sbsim::services
