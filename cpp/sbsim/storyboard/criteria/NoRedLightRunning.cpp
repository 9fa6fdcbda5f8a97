#include "sbsim/storyboard/criteria/NoRedLightRunning.h"

#include <fmt/format.h>

#include <algorithm>

namespace sbsim::storyboard {

namespace {
constexpr std::size_t kNamed = 10;  // vehicles named in the verdict; the rest are counted
}

void NoRedLightRunning::prepare(const EvaluationContext& ctx) {
    const traffic::VehicleSnapshot& s = ctx.snapshot();
    std::unordered_map<std::string, Where> now;
    now.reserve(s.size());
    for (traffic::VehicleSnapshot::Index i = 0; i < s.size(); ++i) {
        const std::string& id = s.ids()[i];
        if (!vehicles_.admits(ctx, id)) continue;
        Where here{s.roadId(i), s.laneId(i)};
        // Only a move onto another road can pass a stop line: a lane change on one road cannot.
        if (const auto it = last_.find(id); it != last_.end() && it->second.road != here.road) {
            const auto passage = ctx.queries().signalPassage(id, it->second.lane, here.lane);
            if (passage && isRed(passage->state)) {
                if (passages_++ == 0) {
                    first_ = fmt::format("{} at {} link {} ('{}') at t={} s", id, passage->link.signal,
                                         passage->link.index, passage->state, ctx.now().str());
                }
                if (runners_.insert(id).second) who_.push_back(id);
            }
        }
        now.emplace(id, std::move(here));
    }
    last_ = std::move(now);  // vehicles that left (or teleport) are forgotten
}

CriterionVerdict NoRedLightRunning::verdict(const CriterionRun& /*run*/) const {
    const std::string expected = "0 red-light passages";
    if (passages_ == 0) return {true, "0 red-light passages", expected};
    std::string names;
    for (std::size_t k = 0; k < std::min(who_.size(), kNamed); ++k) names += (k == 0 ? "" : ", ") + who_[k];
    if (who_.size() > kNamed) names += fmt::format(" and {} more", who_.size() - kNamed);
    return {false,
            fmt::format("{} red-light passage{} by {} vehicle{} ({}), first {}", passages_, passages_ == 1 ? "" : "s",
                        who_.size(), who_.size() == 1 ? "" : "s", names, first_),
            expected};
}

}  // namespace sbsim::storyboard
