#include "sbsim/storyboard/ConditionResult.h"

#include <algorithm>
#include <cassert>
#include <functional>
#include <iterator>

namespace sbsim::storyboard {

ConditionResult ConditionResult::ofOthers(std::vector<VehicleIndex> sortedOthers) {
    assert(std::adjacent_find(sortedOthers.begin(), sortedOthers.end(), std::greater_equal<>()) == sortedOthers.end());
    ConditionResult result(false);
    result.isSet_ = true;
    result.others_ = std::move(sortedOthers);
    return result;
}

ConditionResult ConditionResult::conjunction(const ConditionResult& a, const ConditionResult& b) {
    if (a.isSet_ && b.isSet_) {
        std::vector<VehicleIndex> common;
        std::set_intersection(a.others_.begin(), a.others_.end(), b.others_.begin(), b.others_.end(),
                              std::back_inserter(common));
        return ofOthers(std::move(common));
    }
    // A set narrowed by a plain value: kept when the value is true, as in Artery.
    if (a.isSet_) return b.value_ ? a : ConditionResult(false);
    if (b.isSet_) return a.value_ ? b : ConditionResult(false);
    return a.value_ && b.value_;
}

ConditionResult ConditionResult::disjunction(const ConditionResult& a, const ConditionResult& b) {
    if (a.isSet_ && b.isSet_) {
        std::vector<VehicleIndex> all;
        all.reserve(a.others_.size() + b.others_.size());
        std::set_union(a.others_.begin(), a.others_.end(), b.others_.begin(), b.others_.end(), std::back_inserter(all));
        return ofOthers(std::move(all));
    }
    // A non-empty set wins over a plain value (it names the vehicles); an empty one yields to it.
    if (a.isSet_) return a.isTrue() ? a : b;
    if (b.isSet_) return b.isTrue() ? b : a;
    return a.value_ || b.value_;
}

}  // namespace sbsim::storyboard
