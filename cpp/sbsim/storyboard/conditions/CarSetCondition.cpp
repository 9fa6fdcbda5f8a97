#include "sbsim/storyboard/conditions/CarSetCondition.h"

#include <fmt/format.h>

#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/storyboard/DescribeText.h"

namespace sbsim::storyboard {

CarSetCondition::CarSetCondition(std::set<std::string> ids) : ids_(std::move(ids)), lookup_(ids_.begin(), ids_.end()) {}

void CarSetCondition::prepare(const EvaluationContext& ctx) {
    const traffic::VehicleSnapshot& snapshot = ctx.snapshot();
    if (flagsFor(snapshot)) return;  // the same vehicles as when the flags were made
    const std::vector<std::string>& ids = snapshot.ids();
    flags_.resize(ids.size());
    for (std::size_t k = 0; k < ids.size(); ++k) flags_[k] = lookup_.contains(ids[k]) ? 1 : 0;
    flagsVersion_ = snapshot.idsVersion();
}

ConditionResult CarSetCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const traffic::VehicleSnapshot& snapshot = ctx.snapshot();
    if (flagsFor(snapshot)) return flags_[static_cast<std::size_t>(ego)] != 0;
    return lookup_.contains(snapshot.ids()[ego]);  // not prepared for this id list
}

std::string CarSetCondition::describe() const { return fmt::format("CarSetCondition({})", describeIds(ids_)); }

void CarSetCondition::check(CheckContext& ctx) const {
    std::set<std::string> unknown;
    for (const std::string& id : ids_) {
        if (!ctx.vehicleDefined(id)) unknown.insert(id);
    }
    if (!unknown.empty())
        ctx.warn(fmt::format("CarSetCondition names vehicles no route file defines: {}", describeIds(unknown)));
}

}  // namespace sbsim::storyboard
