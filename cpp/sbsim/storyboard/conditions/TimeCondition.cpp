#include "sbsim/storyboard/conditions/TimeCondition.h"

#include <fmt/format.h>

#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/storyboard/DescribeText.h"

namespace sbsim::storyboard {

TimeCondition::TimeCondition(kernel::SimTime begin, std::optional<kernel::SimTime> end)
    : begin_(begin), end_(end.value_or(kernel::SimTime::max())) {
    if (end_ < begin_) {
        throw std::invalid_argument("TimeCondition: end " + end_.str() + " s is before begin " + begin_.str() + " s");
    }
}

ConditionResult TimeCondition::test(const EvaluationContext& ctx, VehicleIndex /*ego*/) {
    const kernel::SimTime now = ctx.now();
    return begin_ <= now && now <= end_;
}

std::string TimeCondition::describe() const {
    return fmt::format("TimeCondition({}, {})", describeTime(begin_), describeTime(end_));
}

void TimeCondition::check(CheckContext& ctx) const {
    if (begin_ >= ctx.runEnd() || end_ <= ctx.runBegin()) {
        ctx.warn(fmt::format("{} lies outside the run ({} to {})", describe(), describeTime(ctx.runBegin()),
                             describeTime(ctx.runEnd())));
    }
}

}  // namespace sbsim::storyboard
