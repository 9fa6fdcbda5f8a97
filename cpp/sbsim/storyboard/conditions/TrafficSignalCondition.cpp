#include "sbsim/storyboard/conditions/TrafficSignalCondition.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>
#include <string_view>

#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/storyboard/SignalSpec.h"

namespace sbsim::storyboard {

namespace {

/// A letter's colour: SUMO's upper and lower case differ in priority only.
char colour(char letter) {
    return letter == 'G' || letter == 'Y' || letter == 'O' ? static_cast<char>(letter + 32) : letter;
}

}  // namespace

TrafficSignalCondition::TrafficSignalCondition(std::string tls, std::string state, std::vector<int> links)
    : tls_(std::move(tls)), state_(std::move(state)), links_(std::move(links)) {
    checkSignalSpec("TrafficSignalCondition", tls_, state_, links_);
}

bool TrafficSignalCondition::shows(const std::string& now) const {
    if (links_.empty()) {
        if (now.size() != state_.size()) {
            throw std::invalid_argument(
                fmt::format("TrafficSignalCondition: the state '{}' has {} signals, traffic "
                            "light '{}' controls {}",
                            state_, state_.size(), tls_, now.size()));
        }
        for (std::size_t i = 0; i < now.size(); ++i) {
            if (colour(now[i]) != colour(state_[i])) return false;
        }
        return true;
    }
    for (const int link : links_) {
        if (static_cast<std::size_t>(link) >= now.size()) {
            throw std::invalid_argument(
                fmt::format("TrafficSignalCondition: traffic light '{}' has no link {} (it "
                            "controls {})",
                            tls_, link, now.size()));
        }
        if (colour(now[static_cast<std::size_t>(link)]) != colour(state_[0])) return false;
    }
    return true;
}

void TrafficSignalCondition::prepare(const EvaluationContext& ctx) {
    if (readAt_ == ctx.now()) return;
    holds_ = shows(ctx.queries().signalState(tls_));
    readAt_ = ctx.now();
}

ConditionResult TrafficSignalCondition::test(const EvaluationContext& ctx, VehicleIndex /*ego*/) {
    // The board prepares every node before it tests any; alone (one thread), test() reads itself.
    if (readAt_ != ctx.now()) prepare(ctx);
    return holds_;
}

std::string TrafficSignalCondition::describe() const {
    if (links_.empty()) return fmt::format("TrafficSignalCondition('{}' shows '{}')", tls_, state_);
    return fmt::format("TrafficSignalCondition('{}' link{} {} show{} '{}')", tls_, links_.size() == 1 ? "" : "s",
                       fmt::join(links_, ","), links_.size() == 1 ? "s" : "", state_);
}

void TrafficSignalCondition::check(CheckContext& ctx) const {
    ctx.warnUnknown(typeName(), NetworkObject::TrafficLight, {tls_});
}

}  // namespace sbsim::storyboard
