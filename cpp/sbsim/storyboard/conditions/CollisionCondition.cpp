#include "sbsim/storyboard/conditions/CollisionCondition.h"

#include <algorithm>

namespace sbsim::storyboard {

void CollisionCondition::prepare(const EvaluationContext& ctx) {
    const SnapshotStamp stamp = SnapshotStamp::of(ctx.snapshot());
    if (stamp == stamp_) return;
    parties_.clear();
    for (const auto& c : ctx.queries().collisions(ctx.now())) {
        // A party SUMO already removed (collision action "remove") is in no snapshot.
        const auto collider = ctx.snapshot().indexOf(c.collider);
        const auto victim = ctx.snapshot().indexOf(c.victim);
        if (!collider || !victim || *collider == *victim) continue;
        parties_.emplace_back(*collider, *victim);
        parties_.emplace_back(*victim, *collider);
    }
    std::sort(parties_.begin(), parties_.end());
    parties_.erase(std::unique(parties_.begin(), parties_.end()), parties_.end());
    stamp_ = stamp;
}

ConditionResult CollisionCondition::test(const EvaluationContext& ctx, VehicleIndex ego) {
    if (stamp_ != SnapshotStamp::of(ctx.snapshot())) return ConditionResult::ofOthers({});  // not prepared
    std::vector<VehicleIndex> others;
    auto it = std::lower_bound(parties_.begin(), parties_.end(), std::pair<VehicleIndex, VehicleIndex>(ego, -1));
    for (; it != parties_.end() && it->first == ego; ++it) others.push_back(it->second);
    return ConditionResult::ofOthers(std::move(others));
}

}  // namespace sbsim::storyboard
