#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/storyboard/EvaluationContext.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/traffic/SnapshotColumns.h"

namespace sbsim::storyboard {

/// A criterion's result at the end of a run: pass or fail, with what was seen and what was asked,
/// in words a test report can show ("14.2 m/s (veh3 at t=12 s)" against "<= 13.9 m/s").
struct CriterionVerdict {
    bool passed = true;
    std::string actual;
    std::string expected;
};

/// A pass/fail test of a whole run (ScenarioRunner's criteria): it observes every step after the
/// stories acted, and judges at the end. Registered with Storyboard::registerCriterion.
class SBSIM_API Criterion {
public:
    virtual ~Criterion() = default;

    /// How it prints, with its arguments ("MaxSpeed(13.9, vehicles=[a, b])").
    virtual std::string describe() const = 0;
    /// The snapshot values observe() reads.
    virtual traffic::SnapshotColumns columns() const { return {}; }
    /// After each step's stories: what this step shows.
    virtual void observe(const EvaluationContext& /*ctx*/) {}
    /// At the end of the run, over what it observed and the board's stories.
    virtual CriterionVerdict verdict(const std::vector<StoryPtr>& stories) const = 0;

    /// The name given, else describe().
    std::string name() const { return name_.empty() ? describe() : name_; }
    void setName(std::string name) { name_ = std::move(name); }

private:
    std::string name_;
};

using CriterionPtr = std::shared_ptr<Criterion>;

}  // namespace sbsim::storyboard
