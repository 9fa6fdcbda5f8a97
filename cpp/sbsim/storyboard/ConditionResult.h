#pragma once

#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::storyboard {

using VehicleIndex = traffic::VehicleSnapshot::Index;

/// What a condition says about one vehicle: plain true/false, or the set of *other* vehicles that
/// make it true (true iff non-empty). Sets hold snapshot indices in ascending order, which is also
/// ascending id order, so results are reproducible and set algebra is a linear merge.
class SBSIM_API ConditionResult {
public:
    ConditionResult(bool value) : value_(value) {}  // NOLINT: implicit, like Artery's variant
    static ConditionResult ofOthers(std::vector<VehicleIndex> sortedOthers);

    bool isTrue() const { return isSet_ ? !others_.empty() : value_; }
    explicit operator bool() const { return isTrue(); }
    bool isSet() const { return isSet_; }
    /// The other vehicles; empty for a plain true/false result.
    const std::vector<VehicleIndex>& others() const { return others_; }

    /// a ∧ b as the And condition combines them: set ∧ true = set, set ∧ set = intersection.
    static ConditionResult conjunction(const ConditionResult& a, const ConditionResult& b);
    /// a ∨ b as the Or condition combines them: set ∨ false = set, set ∨ set = union.
    static ConditionResult disjunction(const ConditionResult& a, const ConditionResult& b);

private:
    bool value_ = false;
    bool isSet_ = false;
    std::vector<VehicleIndex> others_;
};

}  // namespace sbsim::storyboard
