#include "sbsim/storyboard/criteria/KeepsLane.h"

#include <fmt/format.h>

namespace sbsim::storyboard {

void KeepsLane::observe(const EvaluationContext& ctx) {
    const traffic::VehicleSnapshot& s = ctx.snapshot();
    std::unordered_map<std::string, Where> now;
    for (traffic::VehicleSnapshot::Index i = 0; i < s.size(); ++i) {
        const std::string& id = s.ids()[i];
        if (!vehicles_.admits(ctx, id)) continue;
        Where here{s.roadId(i), s.laneId(i)};
        if (const auto it = last_.find(id);
            it != last_.end() && it->second.road == here.road && it->second.lane != here.lane) {
            if (changes_++ == 0) {
                first_ = fmt::format("{} from {} to {} at t={} s", id, it->second.lane, here.lane, ctx.now().str());
            }
        }
        now.emplace(id, std::move(here));
    }
    last_ = std::move(now);  // vehicles that left are forgotten
}

CriterionVerdict KeepsLane::verdict(const CriterionRun& /*run*/) const {
    if (changes_ == 0) return {true, "0 lane changes", "0 lane changes"};
    return {false, fmt::format("{} lane change{}, first {}", changes_, changes_ == 1 ? "" : "s", first_),
            "0 lane changes"};
}

}  // namespace sbsim::storyboard
