#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::storyboard {

/// Which of a snapshot's interned strings (road, lane or type ids) pass a test, decided once per
/// distinct string: update() (from a condition's prepare(), on one thread) decides the strings new
/// since the last step, and passes() (from test(), on any thread) only reads. `test` is the same
/// predicate on a string in both.
class InternedVerdicts {
public:
    template <typename Test>
    void update(const traffic::VehicleSnapshot& snapshot, const Test& test) {
        if (generation_ != snapshot.internGeneration()) {
            verdicts_.clear();
            generation_ = snapshot.internGeneration();
        }
        const auto& strings = snapshot.interned();
        for (std::size_t k = verdicts_.size(); k < strings.size(); ++k) verdicts_.push_back(test(strings[k]) ? 1 : 0);
    }
    template <typename Test>
    bool passes(const traffic::VehicleSnapshot& snapshot, std::int32_t key, const Test& test) const {
        const auto k = static_cast<std::size_t>(key);
        if (generation_ == snapshot.internGeneration() && k < verdicts_.size()) return verdicts_[k] != 0;
        return test(snapshot.interned()[k]);  // update() was not called for this snapshot
    }

private:
    std::vector<std::uint8_t> verdicts_;
    std::uint64_t generation_ = 0;
};

}  // namespace sbsim::storyboard
