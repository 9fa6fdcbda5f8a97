#include "sbsim/storyboard/criteria/NoRedLightRunning.h"

#include <fmt/format.h>

#include <algorithm>

namespace sbsim::storyboard {

namespace {
constexpr std::size_t kNamed = 10;  // vehicles named in the verdict; the rest are counted
}

void NoRedLightRunning::prepare(const EvaluationContext& ctx) {
    const traffic::VehicleSnapshot& s = ctx.snapshot();
    // The last step's keys index the string table they were made with: the snapshot's own while it
    // only grew, else the copy kept from then.
    const bool sameTable = s.internGeneration() == generation_;
    std::vector<std::string> oldStrings;
    if (sameTable) {
        strings_.insert(strings_.end(), s.interned().begin() + static_cast<std::ptrdiff_t>(strings_.size()),
                        s.interned().end());
    } else {
        oldStrings.swap(strings_);
        strings_ = s.interned();
        generation_ = s.internGeneration();
    }
    const std::vector<std::string>& lastStrings = sameTable ? strings_ : oldStrings;
    now_.clear();
    // Both id lists are sorted: one merge pairs each vehicle with where it was a step ago.
    std::size_t j = 0;
    for (traffic::VehicleSnapshot::Index i = 0; i < s.size(); ++i) {
        const std::string& id = s.ids()[i];
        if (!vehicles_.admits(ctx, id)) continue;
        const std::int32_t road = s.roadKey(i);
        const std::int32_t lane = s.laneKey(i);
        while (j < last_.ids.size() && last_.ids[j] < id) ++j;
        // Only a move onto another road can pass a stop line: a lane change on one road cannot.
        if (j < last_.ids.size() && last_.ids[j] == id &&
            (sameTable ? last_.road[j] != road : lastStrings[last_.road[j]] != s.roadId(i))) {
            const auto passage = ctx.queries().signalPassage(id, lastStrings[last_.lane[j]], s.laneId(i));
            if (passage && isRed(passage->state)) {
                if (passages_++ == 0) {
                    first_ = fmt::format("{} at {} link {} ('{}') at t={} s", id, passage->link.signal,
                                         passage->link.index, passage->state, ctx.now().str());
                }
                if (runners_.insert(id).second) who_.push_back(id);
            }
        }
        now_.ids.push_back(id);
        now_.road.push_back(road);
        now_.lane.push_back(lane);
    }
    std::swap(last_, now_);  // vehicles that left (or teleport) are forgotten
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
