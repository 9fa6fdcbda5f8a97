#pragma once

#include <cstddef>
#include <memory>
#include <set>
#include <string>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/ScenarioMachine.h"
#include "sbsim/storyboard/conditions/VehicleIdMap.h"

namespace sbsim::storyboard {

/// True while an element of an OpenSCENARIO storyboard (ScenarioMachine) is running: for the
/// element's actors (an event's ManeuverGroup actors), or for the world when it has none (an act:
/// a WorldStory). When the element's ManeuverGroup selects triggering entities, the entities that
/// started its Act are actors too (ScenarioMachine::selectedActors, asked each step). Its first
/// test of a step advances the machine, on the step's snapshot; its
/// children, for the board to prepare and `sbsim check` to print, are the element's trigger
/// conditions.
class ElementCondition : public Condition {
public:
    /// Throws std::invalid_argument for a null machine or an element it does not have.
    ElementCondition(std::shared_ptr<ScenarioMachine> machine, std::size_t element, std::set<std::string> actors = {});

    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void prepare(const EvaluationContext& ctx) override { machine_->prepare(ctx); }
    traffic::SnapshotColumns columns() const override { return {}; }
    bool timeOnly() const override { return actors_.empty() && !selects_; }
    void forEachChild(const std::function<void(Condition&)>& visit) const override {
        machine_->forEachCondition(element_, visit);
    }
    std::string describe() const override;
    void check(CheckContext& ctx) const override;

    const std::shared_ptr<ScenarioMachine>& machine() const { return machine_; }
    std::size_t element() const { return element_; }
    const std::set<std::string>& actors() const { return actors_; }

private:
    std::shared_ptr<ScenarioMachine> machine_;
    std::size_t element_;
    std::set<std::string> actors_;
    VehicleIdSet lookup_;  // the actors, hashed
    bool selects_;         // its ManeuverGroup selects triggering entities
};

}  // namespace sbsim::storyboard
