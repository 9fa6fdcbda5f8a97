#include "sbsim/storyboard/effects/TrafficLightPhaseEffect.h"

#include <fmt/format.h>

#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"

namespace sbsim::storyboard {

TrafficLightPhaseEffect::TrafficLightPhaseEffect(std::string tls, int phase) : tls_(std::move(tls)), phase_(phase) {
    if (tls_.empty()) throw std::invalid_argument("TrafficLightPhaseEffect needs a traffic light id");
    if (phase_ < 0) throw std::invalid_argument(fmt::format("TrafficLightPhaseEffect: phase {} < 0", phase_));
}

std::string TrafficLightPhaseEffect::describe() const {
    return fmt::format("TrafficLightPhaseEffect('{}', phase {})", tls_, phase_);
}

void TrafficLightPhaseEffect::check(CheckContext& ctx) const {
    ctx.warnUnknown(typeName(), NetworkObject::TrafficLight, {tls_});
}

}  // namespace sbsim::storyboard
