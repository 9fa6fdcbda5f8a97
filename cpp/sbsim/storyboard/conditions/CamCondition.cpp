#include "sbsim/storyboard/conditions/CamCondition.h"

#include <fmt/format.h>

#include <algorithm>

namespace sbsim::storyboard {

CamCondition::CamCondition(std::optional<double> distance, std::optional<kernel::SimTime> maxAge)
    : distance_(distance), maxAge_(maxAge) {}

ConditionResult CamCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    const auto& snapshot = ctx.snapshot();
    const facilities::StationFacilities* station =
        ctx.stations() == nullptr ? nullptr : ctx.stations()->find(snapshot.ids()[ego]);
    if (station == nullptr) return false;
    const kernel::SimTime now = ctx.now();
    const Eigen::Vector2d here = snapshot.positions().col(ego);
    bool any = false;
    std::vector<VehicleIndex> known;
    for (const auto& [id, entry] : station->ldm.entries()) {
        if (entry.expiry() < now) continue;
        if (maxAge_ && entry.age(now) > *maxAge_) continue;
        if (distance_ && (entry.cam.position - here).norm() > *distance_) continue;
        any = true;
        const auto index = snapshot.indexOf(id);
        if (index && *index != ego) known.push_back(*index);
    }
    if (!any) return false;
    if (known.empty()) return true;
    std::sort(known.begin(), known.end());  // ascending, as the snapshot (the LDM has no order)
    return ConditionResult::ofOthers(std::move(known));
}

std::string CamCondition::describe() const {
    std::string out = "CamCondition(";
    out += distance_ ? fmt::format("within {:g} m", *distance_) : "any distance";
    if (maxAge_) out += ", max age " + maxAge_->str() + " s";
    return out + ")";
}

}  // namespace sbsim::storyboard
