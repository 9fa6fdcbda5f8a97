#include "sbsim/storyboard/conditions/HeadwayCondition.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sbsim::storyboard {

HeadwayCondition::HeadwayCondition(double seconds) : seconds_(seconds) {
    if (!std::isfinite(seconds) || seconds <= 0)
        throw std::invalid_argument("HeadwayCondition: seconds must be > 0, not " + std::to_string(seconds));
}

ConditionResult HeadwayCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const traffic::VehicleSnapshot& snapshot = ctx.snapshot();
    const double speed = snapshot.speeds()[ego];
    if (speed < standingSpeed) return ConditionResult::ofOthers({});
    const auto leader = ctx.queries().leader(snapshot.ids()[ego], std::max(minLookAhead, speed * seconds_ * 2));
    if (!leader || leader->gap / speed >= seconds_) return ConditionResult::ofOthers({});
    const auto index = snapshot.indexOf(leader->id);
    if (!index) return ConditionResult::ofOthers({});  // not in this step's snapshot (just inserted)
    return ConditionResult::ofOthers({*index});
}

std::string HeadwayCondition::describe() const { return fmt::format("HeadwayCondition({:g} s)", seconds_); }

}  // namespace sbsim::storyboard
