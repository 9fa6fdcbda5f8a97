#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/Effect.h"
#include "sbsim/traffic/NeighbourGrid.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::storyboard {

/// The storyboard state machine of ASAM OpenSCENARIO 1.2 (section "Storyboard element states"):
/// Storyboard → Story → Act → ManeuverGroup → Maneuver → Event, each in standby, running or
/// complete, moved by start, end, stop and skip transitions. An `.xosc` run builds one machine;
/// each Act and Event is an ordinary story whose condition (ElementCondition) asks the machine
/// whether that element runs, so the event log, report and GUI see the scenario's elements.
///
/// The machine advances once per step, on the step's snapshot, before any story acts:
/// elements in the order they were added (parents first), then completions bottom up.
/// - Story, ManeuverGroup, Maneuver start when their parent runs; an Act or Event starts when its
///   parent runs and its start trigger fires (no trigger: at once). The storyboard starts at the
///   first step its start trigger fires (the end of its Init: its entities are on the road).
/// - A trigger is an OR of AND groups of conditions; each condition has its own edge (rising,
///   falling, risingOrFalling, none; the value before its first evaluation counts as false) and
///   delay (its edge-processed value is seen `delay` s later). A start trigger is evaluated every
///   step its element's parent runs until the element completes (so its edges compare consecutive
///   steps, also while the element runs); it starts the element only from standby. A condition
///   not evaluated at the step before forgets its previous value. Conditions are time-only
///   (TimeCondition, EntityCondition, ...): the machine evaluates them once, not per vehicle.
/// - An Event completes when all its actions do (addAction: each effect's complete()). A started
///   event runs at least for the step it started in; from the next step on it ends
///   (endTransition) at the first step all its actions report complete — at once for one-shot
///   effects (SetSpeedEffect: so one step), when its target is reached for a transition
///   (SpeedChangeEffect, LaneChangeEffect, LaneOffsetEffect), never for a continuous one (it runs
///   until stopped) — back to standby while executions are left (maximumExecutionCount), else
///   complete. It never restarts in the step it ended. The entity keeps the reached state after:
///   an effect that completed leaves its final command in force when its story ends (a speed
///   change sets its target speed once more, as SetSpeedEffect does); a stopped one does not.
///   Priority: `overwrite` stops (stopTransition → complete) every running event of its
///   maneuver; `skip` does not start while another of its maneuver runs (skipTransition);
///   `parallel` starts regardless.
/// - A ManeuverGroup that ended (all its children complete) goes back to standby while executions
///   are left (maximumExecutionCount), its maneuvers and events back to standby with no executions
///   and fresh trigger memories, and starts again at the next step; else it completes.
/// - Triggering entities: a trigger condition's true result names the entities it holds for (its
///   others: TriggeringEntitiesCondition). An element's start records the entities of the
///   conditions of the groups that fired. A ManeuverGroup with selectTriggeringEntities takes the
///   entities that fired its Act's start trigger as actors (actors()), besides its own.
/// - An element whose parent is no longer running is stopped. A Maneuver, ManeuverGroup, Act or
///   Story completes (endTransition) when all its children are complete. An Act's or the
///   Storyboard's stop trigger stops it; the Storyboard's stop ends the run (onEnd()).
class SBSIM_API ScenarioMachine {
public:
    enum class Kind { storyboard, story, act, maneuverGroup, maneuver, event };
    enum class State { standby, running, complete };
    enum class Transition { none, start, end, stop, skip };
    enum class Edge { none, rising, falling, risingOrFalling };
    enum class Priority { parallel, overwrite, skip };

    struct TriggerCondition {
        std::string name;
        ConditionPtr condition;
        Edge edge = Edge::none;
        double delay = 0;  ///< s
    };
    /// OR of AND groups; empty: no trigger.
    using Trigger = std::vector<std::vector<TriggerCondition>>;

    struct ElementSpec {
        std::string name;
        Kind kind = Kind::event;
        std::optional<std::size_t> parent;  ///< none only for the storyboard
        Trigger start;
        Trigger stop;  ///< acts and the storyboard
        std::uint64_t maxExecutions = 1;
        Priority priority = Priority::parallel;
        bool selectTriggeringEntities = false;  ///< maneuver groups
    };

    ScenarioMachine() = default;
    ScenarioMachine(const ScenarioMachine&) = delete;
    ScenarioMachine& operator=(const ScenarioMachine&) = delete;

    /// Adds an element and returns its index. The first is the storyboard (no parent); every
    /// other names an element added before it, of the kind above its own. Throws
    /// std::invalid_argument for a wrong parent, a null or not time-only trigger condition, a
    /// negative delay, zero executions, or a start trigger on a Story, ManeuverGroup or Maneuver.
    std::size_t add(ElementSpec spec);
    std::size_t size() const { return elements_.size(); }
    const std::string& name(std::size_t element) const { return at(element).spec.name; }
    Kind kind(std::size_t element) const { return at(element).spec.kind; }

    /// Keeps the step's context for advance() (the board prepares every node before any story is
    /// tested; the context lives until that step's stories acted).
    void prepare(const EvaluationContext& ctx);
    /// Advances the machine to the prepared step's time; later calls at that time do nothing.
    /// Without a prepared context (a test of one snapshot), advances on `ctx`.
    void advance(const EvaluationContext& ctx);

    /// Adds an action (the effect its event's story applies) to `event`, which then ends only once
    /// every action of it is complete(). Throws std::invalid_argument for a null effect or an
    /// element that is not an event.
    void addAction(std::size_t event, std::shared_ptr<const Effect> action);

    State state(std::size_t element) const { return at(element).state; }
    /// Whether `element` made transition `t` at time `now` (this step, once advanced).
    bool transitionedAt(std::size_t element, Transition t, kernel::SimTime now) const;
    /// How often the element started so far (since its ManeuverGroup last started).
    std::uint64_t executions(std::size_t element) const { return at(element).executions; }
    /// The entities that fired the element's start trigger when it last started (ascending ids).
    const std::vector<std::string>& triggeringEntities(std::size_t element) const { return at(element).triggeredBy; }
    /// Whether the ManeuverGroup above `element` (or `element` itself) selects triggering entities.
    bool selectsTriggeringEntities(std::size_t element) const;
    /// The actors chosen at run time for `element` (an event, maneuver or group): the entities that
    /// started its Act, when its ManeuverGroup selects triggering entities; else none.
    const std::vector<std::string>& selectedActors(std::size_t element) const;
    /// Whether the storyboard was stopped (the run ends).
    bool ended() const { return ended_; }
    /// Called once when the storyboard's stop trigger fires.
    void onEnd(std::function<void()> f) { onEnd_ = std::move(f); }

    /// Calls `visit` on each condition of the element's triggers (start, then stop).
    void forEachCondition(std::size_t element, const std::function<void(Condition&)>& visit) const;
    /// The element's triggers in one line, e.g. "start: (SpeedCondition rising) or (...)".
    std::string describeTriggers(std::size_t element) const;

    static const char* kindName(Kind k);
    static const char* stateName(State s);
    static const char* transitionName(Transition t);

private:
    struct ConditionMemory {
        bool last = false;
        std::optional<kernel::SimTime> evaluated;  ///< the step it was last evaluated
        /// Edge-processed true results awaiting their delay, with the entities they held for.
        std::deque<std::pair<kernel::SimTime, std::vector<std::string>>> pending;
    };
    struct Element {
        ElementSpec spec;
        std::vector<std::size_t> children;
        State state = State::standby;
        Transition transition = Transition::none;
        std::optional<kernel::SimTime> transitionTime;
        std::optional<kernel::SimTime> started;
        std::uint64_t executions = 0;
        std::vector<std::vector<ConditionMemory>> startMemory;
        std::vector<std::vector<ConditionMemory>> stopMemory;
        std::vector<std::shared_ptr<const Effect>> actions;  ///< an event's
        std::vector<std::string> triggeredBy;                ///< at its last start
    };

    const Element& at(std::size_t element) const;
    void step(const EvaluationContext& ctx);
    /// Whether `trigger` fires; the entities of the fired groups' conditions go to `entities`.
    bool fires(const Trigger& trigger, std::vector<std::vector<ConditionMemory>>& memory, const EvaluationContext& ctx,
               VehicleIndex ego, std::vector<std::string>* entities = nullptr);
    std::optional<std::size_t> groupOf(std::size_t element) const;
    void resetSubtree(std::size_t element);
    bool parentRunning(const Element& e) const;
    void move(Element& e, State to, Transition t);
    void stopSubtree(std::size_t element);

    std::vector<Element> elements_;
    const EvaluationContext* prepared_ = nullptr;
    std::optional<kernel::SimTime> advanced_;
    std::optional<kernel::SimTime> previous_;  ///< the step before advanced_
    bool ended_ = false;
    std::function<void()> onEnd_;
    // The one-row snapshot triggers are evaluated on when no vehicle runs (as a WorldStory's).
    traffic::VehicleSnapshot empty_;
    traffic::NeighbourGrid emptyGrid_;
};

}  // namespace sbsim::storyboard
