#pragma once

#include <cstddef>
#include <string>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Criterion.h"

namespace sbsim::storyboard {

/// Passes when SUMO reported no collision during the run (its collision list, asked each step).
class NoCollision : public Criterion {
public:
    std::string describe() const override { return "NoCollision()"; }
    void observe(const EvaluationContext& ctx) override;
    CriterionVerdict verdict(const CriterionRun& run) const override;

private:
    std::size_t collisions_ = 0;
    std::string first_;  // "a with b at t=12 s"
};

}  // namespace sbsim::storyboard
