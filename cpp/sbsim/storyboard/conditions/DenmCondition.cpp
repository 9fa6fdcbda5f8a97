#include "sbsim/storyboard/conditions/DenmCondition.h"

#include <algorithm>

namespace sbsim::storyboard {

DenmCondition::DenmCondition(std::optional<int> cause, std::optional<kernel::SimTime> maxAge)
    : cause_(cause), maxAge_(maxAge) {}

ConditionResult DenmCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const auto& snapshot = ctx.snapshot();
    const facilities::StationFacilities* station =
        ctx.stations() == nullptr ? nullptr : ctx.stations()->find(snapshot.ids()[ego]);
    if (station == nullptr) return false;
    const kernel::SimTime now = ctx.now();
    bool any = false;
    std::vector<VehicleIndex> originators;
    for (const auto& [action, entry] : station->denms.entries()) {
        if (entry.denm.expiry() < now) continue;
        if (cause_ && entry.denm.cause != *cause_) continue;
        if (maxAge_ && now - entry.lastHeardAt > *maxAge_) continue;
        any = true;
        const auto index = snapshot.indexOf(action.station);
        if (index && *index != ego) originators.push_back(*index);
    }
    if (!any) return false;
    if (originators.empty()) return true;
    std::sort(originators.begin(), originators.end());
    originators.erase(std::unique(originators.begin(), originators.end()), originators.end());
    return ConditionResult::ofOthers(std::move(originators));
}

std::string DenmCondition::describe() const {
    std::string out = "DenmCondition(";
    out += cause_ ? "cause " + std::to_string(*cause_) : "any cause";
    if (maxAge_) out += ", max age " + maxAge_->str() + " s";
    return out + ")";
}

}  // namespace sbsim::storyboard
