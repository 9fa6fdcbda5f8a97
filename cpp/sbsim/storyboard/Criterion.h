#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Statistics.h"
#include "sbsim/storyboard/CheckContext.h"
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

/// What a criterion judges at the end besides what it observed: the board's stories, the run's
/// statistics, and the event log's lines (JSON Lines; empty unless a criterion needsEvents()).
struct CriterionRun {
    const std::vector<StoryPtr>& stories;
    const kernel::Statistics* statistics = nullptr;
    std::string_view events;
};

/// A pass/fail test of a whole run (ScenarioRunner's criteria): it observes every step (before
/// and after the stories act), and judges at the end. Registered with Storyboard::registerCriterion.
class SBSIM_API Criterion {
public:
    virtual ~Criterion() = default;

    /// How it prints, with its arguments ("MaxSpeed(13.9, vehicles=[a, b])").
    virtual std::string describe() const = 0;
    /// The snapshot values observe() reads.
    virtual traffic::SnapshotColumns columns() const { return {}; }
    /// Before each step's stories act: what the step's traffic did under the network as it moved
    /// (a story's effect may switch a traffic light before observe() sees the step).
    virtual void prepare(const EvaluationContext& /*ctx*/) {}
    /// After each step's stories: what this step shows.
    virtual void observe(const EvaluationContext& /*ctx*/) {}
    /// Whether it reads the stations' DENM memories, which only a DEN service fills: a run without
    /// one refuses it (exit 2) rather than fail every vehicle as unwarned.
    virtual bool readsDenmMemory() const { return false; }
    /// What `sbsim check` warns of and a run refuses: the ids it names that the scenario lacks.
    virtual void check(CheckContext& /*ctx*/) const {}
    /// Whether verdict() reads the event log (the board then keeps its lines in memory).
    virtual bool needsEvents() const { return false; }
    /// At the end of the run, over what it observed and `run`.
    virtual CriterionVerdict verdict(const CriterionRun& run) const = 0;

    /// The name given, else describe().
    std::string name() const { return name_.empty() ? describe() : name_; }
    void setName(std::string name) { name_ = std::move(name); }

private:
    std::string name_;
};

using CriterionPtr = std::shared_ptr<Criterion>;

}  // namespace sbsim::storyboard
