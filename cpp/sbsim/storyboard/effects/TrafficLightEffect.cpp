#include "sbsim/storyboard/effects/TrafficLightEffect.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>
#include <string_view>

#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/storyboard/SignalSpec.h"

namespace sbsim::storyboard {

TrafficLightEffect::TrafficLightEffect(std::string tls, std::string state, std::vector<int> links, bool keep)
    : tls_(std::move(tls)), state_(std::move(state)), links_(std::move(links)), keep_(keep) {
    checkSignalSpec("TrafficLightEffect", tls_, state_, links_);
}

std::string TrafficLightEffect::describe() const {
    std::string s = fmt::format("TrafficLightEffect('{}', '{}'", tls_, state_);
    if (!links_.empty()) s += fmt::format(", link{} {}", links_.size() == 1 ? "" : "s", fmt::join(links_, ","));
    return s + (keep_ ? ", kept)" : ")");
}

void TrafficLightEffect::check(CheckContext& ctx) const {
    ctx.warnUnknown(typeName(), NetworkObject::TrafficLight, {tls_});
}

void TrafficLightEffect::apply(WorldScope& scope) {
    if (links_.empty()) {
        scope.stack().pushSignalState(scope.token(), tls_, state_);
        return;
    }
    if (!scope.network().hasTrafficLight(tls_)) {
        throw std::invalid_argument(fmt::format("no traffic light '{}' in the network", tls_));
    }
    std::string whole = scope.network().signalState(tls_);
    for (const int link : links_) {
        if (static_cast<std::size_t>(link) >= whole.size()) {
            throw std::invalid_argument(
                fmt::format("traffic light '{}' has no link {} (it controls {})", tls_, link, whole.size()));
        }
        whole[static_cast<std::size_t>(link)] = state_[0];
    }
    scope.stack().pushSignalState(scope.token(), tls_, whole);
}

}  // namespace sbsim::storyboard
