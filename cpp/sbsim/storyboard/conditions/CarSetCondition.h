#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/VehicleIdMap.h"

namespace sbsim::storyboard {

/// True for the vehicles whose id is in the given set.
class CarSetCondition : public Condition {
public:
    explicit CarSetCondition(std::set<std::string> ids);
    traffic::SnapshotColumns columns() const override { return {}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    /// Looks the ids up once per id list (VehicleSnapshot::idsVersion()), not once per vehicle and
    /// step: while no vehicle comes or goes, test() reads a flag by index.
    void prepare(const EvaluationContext& ctx) override;
    /// Whether test() reads flags made for this id list rather than hashing the ego's id.
    bool flagsFor(const traffic::VehicleSnapshot& snapshot) const {
        return flagsVersion_ == snapshot.idsVersion() && flags_.size() == static_cast<std::size_t>(snapshot.size());
    }
    std::string describe() const override;
    /// Warns about ids no route file (and no story) defines.
    void check(CheckContext& ctx) const override;
    const std::set<std::string>& ids() const { return ids_; }

    bool pure() const override { return true; }

private:
    std::set<std::string> ids_;
    VehicleIdSet lookup_;  // the same ids, hashed
    // Per index of the id list whose idsVersion() is flagsVersion_ (0: none): 1 if in the set.
    std::uint64_t flagsVersion_ = 0;
    std::vector<std::uint8_t> flags_;
};

}  // namespace sbsim::storyboard
