#include "sbsim/storyboard/effects/TrafficLightEffect.h"

#include <fmt/format.h>

#include <stdexcept>
#include <string_view>

#include "sbsim/storyboard/CheckContext.h"

namespace sbsim::storyboard {

TrafficLightEffect::TrafficLightEffect(std::string tls, std::string state)
    : tls_(std::move(tls)), state_(std::move(state)) {
    if (tls_.empty()) throw std::invalid_argument("TrafficLightEffect needs a traffic light id");
    if (state_.empty()) throw std::invalid_argument("TrafficLightEffect needs a state, one letter per signal");
    constexpr std::string_view kLetters = "GgrsuyYoO";  // SUMO's signal states
    if (const auto bad = state_.find_first_not_of(kLetters); bad != std::string::npos) {
        throw std::invalid_argument(fmt::format("TrafficLightEffect state '{}': '{}' is not a signal letter ({})",
                                                state_, state_[bad], kLetters));
    }
}

std::string TrafficLightEffect::describe() const { return fmt::format("TrafficLightEffect('{}', '{}')", tls_, state_); }

void TrafficLightEffect::check(CheckContext& ctx) const {
    ctx.warnUnknown(typeName(), NetworkObject::TrafficLight, {tls_});
}

}  // namespace sbsim::storyboard
