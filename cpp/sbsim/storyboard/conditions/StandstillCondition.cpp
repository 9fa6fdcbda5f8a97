#include "sbsim/storyboard/conditions/StandstillCondition.h"

#include <fmt/format.h>

#include <stdexcept>

#include "sbsim/storyboard/DescribeText.h"

namespace sbsim::storyboard {

using kernel::SimTime;

StandstillCondition::StandstillCondition(SimTime duration) : duration_(duration) {
    if (duration_ < SimTime::zero())
        throw std::invalid_argument("StandstillCondition: duration " + duration_.str() + " s is negative");
}

void StandstillCondition::prepare(const EvaluationContext& ctx) {
    const traffic::VehicleSnapshot& snapshot = ctx.snapshot();
    const SnapshotStamp stamp = SnapshotStamp::of(snapshot);
    if (stamp == stamp_) return;  // this step is done
    const SimTime now = snapshot.time();
    const auto& ids = snapshot.ids();
    const auto& speeds = snapshot.speeds();
    // Both id lists ascend: one merge carries each vehicle's standing time over.
    sinceScratch_.assign(ids.size(), SimTime::max());
    std::size_t j = 0;
    for (std::size_t k = 0; k < ids.size(); ++k) {
        if (!(speeds[static_cast<Eigen::Index>(k)] < standingSpeed)) continue;
        while (j < ids_.size() && ids_[j] < ids[k]) ++j;
        const bool stoodBefore = j < ids_.size() && ids_[j] == ids[k] && since_[j] != SimTime::max();
        sinceScratch_[k] = stoodBefore ? since_[j] : now;
    }
    std::swap(since_, sinceScratch_);
    ids_ = ids;
    stamp_ = stamp;
}

ConditionResult StandstillCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    if (stamp_ != SnapshotStamp::of(ctx.snapshot()))  // not prepared for this step: it only knows now
        return duration_ == SimTime::zero() && ctx.snapshot().speeds()[ego] < standingSpeed;
    const SimTime since = since_[static_cast<std::size_t>(ego)];
    return since != SimTime::max() && ctx.now() - since >= duration_;
}

std::string StandstillCondition::describe() const {
    return fmt::format("StandstillCondition({})", describeTime(duration_));
}

}  // namespace sbsim::storyboard
