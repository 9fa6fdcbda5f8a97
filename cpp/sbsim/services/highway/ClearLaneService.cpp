#include "sbsim/services/highway/ClearLaneService.h"

#include <fmt/format.h>

#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/highway/ClearLaneMessage.h"

namespace sbsim::services {

SBSIM_REGISTER_SERVICE(ClearLaneService);

void ClearLaneService::initialize() { speed_ = numberParameter("speed", 25.0); }

void ClearLaneService::indicate(const radio::V2xMessage& message) {
    const auto* clear = dynamic_cast<const ClearLaneMessage*>(&message);
    if (clear == nullptr || slowed_) return;
    const auto self = selfIndex();
    if (!self || snapshot().roadId(*self) != clear->road()) return;
    const std::string& lane = snapshot().laneId(*self);
    if (lane == fmt::format("{}_{}", clear->road(), clear->lane())) return;  // SUMO's lane id: <edge>_<index>
    vehicle().setMaxSpeed(speed_);
    slowed_ = true;
}

}  // namespace sbsim::services
