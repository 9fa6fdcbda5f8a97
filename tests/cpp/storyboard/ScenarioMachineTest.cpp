// OpenSCENARIO's storyboard state machine (ScenarioMachine): starts, ends, maximumExecutionCount
// (of events and of maneuver groups), condition edges and delays, priorities, stop triggers,
// StoryboardElementStateCondition, triggering entities and selectTriggeringEntities; and the
// conditions that tie it to stories: EntityCondition, TriggeringEntitiesCondition, ElementCondition.

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "StoryboardTestSupport.h"
#include "sbsim/storyboard/ScenarioMachine.h"
#include "sbsim/storyboard/ScenarioParameters.h"
#include "sbsim/storyboard/conditions/ElementCondition.h"
#include "sbsim/storyboard/conditions/ElementStateCondition.h"
#include "sbsim/storyboard/conditions/EntityCondition.h"
#include "sbsim/storyboard/conditions/ParameterCondition.h"
#include "sbsim/storyboard/conditions/SpeedCondition.h"
#include "sbsim/storyboard/conditions/TriggeringEntitiesCondition.h"

namespace sbsim::storyboard::test {
namespace {

using M = ScenarioMachine;

/// A time-only condition whose value the test sets.
class Switch : public Condition {
public:
    ConditionResult test(const EvaluationContext& /*ctx*/, VehicleIndex /*ego*/) override { return on; }
    bool timeOnly() const override { return true; }
    bool on = false;
};

/// A storyboard → story → act → group → maneuver skeleton, stepping 1 s at a time.
class Machine : public ::testing::Test {
protected:
    Machine() {
        board = m->add({"Storyboard", M::Kind::storyboard});
        story = m->add({"S", M::Kind::story, board});
        act = m->add({"A", M::Kind::act, story});
        group = m->add({"G", M::Kind::maneuverGroup, act});
        maneuver = m->add({"M", M::Kind::maneuver, group});
    }
    static M::Trigger when(const std::shared_ptr<Condition>& c, M::Edge edge = M::Edge::none, double delay = 0) {
        return {{{"c", c, edge, delay}}};
    }
    std::size_t event(const std::string& name, M::Trigger start, std::uint64_t max = 1,
                      M::Priority priority = M::Priority::parallel) {
        return m->add({name, M::Kind::event, maneuver, std::move(start), {}, max, priority});
    }
    /// Advances one step (t = 1, 2, ...) and returns whether `element` runs.
    bool step(std::size_t element) {
        scene.set({car("a", 0, 0, speed), car("b", 10, 0, 0)}, SimTime::fromSeconds(++t));
        m->advance(scene.ctx());
        return m->state(element) == M::State::running;
    }
    /// The steps (of `steps` more) at which `element` runs.
    std::vector<int> runs(std::size_t element, int steps, const std::function<void(int)>& before = {}) {
        std::vector<int> at;
        for (int i = 0; i < steps; ++i) {
            if (before) before(t + 1);
            if (step(element)) at.push_back(t);
        }
        return at;
    }

    std::shared_ptr<M> m = std::make_shared<M>();
    std::size_t board, story, act, group, maneuver;
    Scene scene{{car("a", 0, 0), car("b", 10, 0)}};
    int t = 0;
    double speed = 0;
};

TEST_F(Machine, AnEventWithoutTriggerRunsForItsFirstStepThenCompletes) {
    const std::size_t e = event("E", {});
    EXPECT_EQ(runs(e, 3), (std::vector<int>{1}));
    EXPECT_EQ(m->state(e), M::State::complete);
    EXPECT_TRUE(m->transitionedAt(e, M::Transition::end, SimTime::fromSeconds(2)) ||
                m->state(maneuver) == M::State::complete);
    EXPECT_EQ(m->state(maneuver), M::State::complete) << "its only event completed";
    EXPECT_EQ(m->state(act), M::State::complete);
    EXPECT_EQ(m->state(board), M::State::running) << "the storyboard runs until its stop trigger";
}

TEST_F(Machine, MaximumExecutionCountTwoFiresOnTwoRisingEdgesOnly) {
    auto sw = std::make_shared<Switch>();
    const std::size_t e = event("E", when(sw, M::Edge::rising), 2);
    // On at 2-3, 5-6, 8-9: three rising edges; the third finds the event complete.
    const auto at =
        runs(e, 10, [&](int next) { sw->on = next == 2 || next == 3 || next == 5 || next == 6 || next == 8; });
    EXPECT_EQ(at, (std::vector<int>{2, 5}));
    EXPECT_EQ(m->executions(e), 2u);
    EXPECT_EQ(m->state(e), M::State::complete);
}

TEST_F(Machine, AFallingEdgeFiresWhenTheConditionTurnsFalse) {
    auto sw = std::make_shared<Switch>();
    const std::size_t e = event("E", when(sw, M::Edge::falling));
    const auto at = runs(e, 6, [&](int next) { sw->on = next >= 2 && next <= 3; });
    EXPECT_EQ(at, (std::vector<int>{4}));
}

TEST_F(Machine, RisingOrFallingFiresOnBoth) {
    auto sw = std::make_shared<Switch>();
    const std::size_t e = event("E", when(sw, M::Edge::risingOrFalling), 5);
    const auto at = runs(e, 8, [&](int next) { sw->on = next >= 2 && next <= 4; });
    EXPECT_EQ(at, (std::vector<int>{2, 5}));
}

TEST_F(Machine, EdgeNoneFiresWhileTrueButNotInTheStepItEnded) {
    auto sw = std::make_shared<Switch>();
    sw->on = true;
    const std::size_t e = event("E", when(sw), 3);
    EXPECT_EQ(runs(e, 7), (std::vector<int>{1, 3, 5}));
}

TEST_F(Machine, ADelayedConditionIsSeenThatMuchLater) {
    auto sw = std::make_shared<Switch>();
    const std::size_t e = event("E", when(sw, M::Edge::rising, 3));
    const auto at = runs(e, 8, [&](int next) { sw->on = next >= 2; });
    EXPECT_EQ(at, (std::vector<int>{5}));
}

TEST_F(Machine, OverwriteStopsTheRunningEventsOfItsManeuver) {
    auto sw = std::make_shared<Switch>();
    auto late = std::make_shared<Switch>();
    const std::size_t a = event("A", when(sw), 1);
    const std::size_t b = event("B", when(late), 1, M::Priority::overwrite);
    sw->on = true;
    late->on = true;
    EXPECT_TRUE(step(b));
    EXPECT_EQ(m->state(a), M::State::complete);
    EXPECT_TRUE(m->transitionedAt(a, M::Transition::stop, SimTime::fromSeconds(1)));
    EXPECT_EQ(m->executions(a), 1u);
}

/// An action whose completion the test sets (a transition reaching its target).
class Transition : public Effect {
public:
    void apply(EffectScope& /*scope*/) override {}
    void remove(EffectScope& /*scope*/) override {}
    bool complete() const override { return done; }
    bool done = false;
};

TEST_F(Machine, AnEventRunsUntilAllItsActionsAreComplete) {
    const std::size_t e = event("E", {});
    auto first = std::make_shared<Transition>();
    auto second = std::make_shared<Transition>();
    m->addAction(e, first);
    m->addAction(e, second);
    // First done from step 3 on, second from step 5 on: the event ends at 5, its maneuver with it.
    const auto at = runs(e, 7, [&](int next) {
        first->done = next >= 3;
        second->done = next >= 5;
    });
    EXPECT_EQ(at, (std::vector<int>{1, 2, 3, 4}));
    EXPECT_TRUE(m->transitionedAt(e, M::Transition::end, SimTime::fromSeconds(5)));
    EXPECT_EQ(m->state(maneuver), M::State::complete);
}

TEST_F(Machine, ACompleteActionStillRunsItsFirstStep) {
    const std::size_t e = event("E", {});
    auto done = std::make_shared<Transition>();
    done->done = true;
    m->addAction(e, done);
    EXPECT_EQ(runs(e, 3), (std::vector<int>{1}));
}

TEST_F(Machine, OverwriteStopsARunningTransition) {
    auto late = std::make_shared<Switch>();
    const std::size_t a = event("A", {});
    auto never = std::make_shared<Transition>();
    m->addAction(a, never);
    const std::size_t b = event("B", when(late), 1, M::Priority::overwrite);
    EXPECT_EQ(runs(a, 3, [&](int next) { late->on = next >= 3; }), (std::vector<int>{1, 2}));
    EXPECT_TRUE(m->transitionedAt(a, M::Transition::stop, SimTime::fromSeconds(3)));
    EXPECT_EQ(m->state(b), M::State::running);
}

TEST_F(Machine, OnlyAnEventTakesActions) {
    EXPECT_THROW(m->addAction(maneuver, std::make_shared<Transition>()), std::invalid_argument);
    EXPECT_THROW(m->addAction(event("E", {}), nullptr), std::invalid_argument);
}

TEST_F(Machine, SkipDoesNotStartWhileAnotherEventOfItsManeuverRuns) {
    auto sw = std::make_shared<Switch>();
    const std::size_t a = event("A", when(sw), 1);
    const std::size_t b = event("B", when(sw), 2, M::Priority::skip);
    sw->on = true;
    EXPECT_FALSE(step(b));
    EXPECT_TRUE(m->state(a) == M::State::running);
    EXPECT_TRUE(m->transitionedAt(b, M::Transition::skip, SimTime::fromSeconds(1)));
    EXPECT_TRUE(step(b)) << "A ended at t=2: B starts";
    EXPECT_EQ(m->executions(b), 1u);
}

TEST_F(Machine, ParallelEventsRunTogether) {
    auto sw = std::make_shared<Switch>();
    const std::size_t a = event("A", when(sw));
    const std::size_t b = event("B", when(sw));
    sw->on = true;
    EXPECT_TRUE(step(b));
    EXPECT_EQ(m->state(a), M::State::running);
}

TEST_F(Machine, AnEventWaitsForItsAct) {
    auto go = std::make_shared<Switch>();
    auto m2 = std::make_shared<M>();
    const std::size_t sb = m2->add({"Storyboard", M::Kind::storyboard});
    const std::size_t s = m2->add({"S", M::Kind::story, sb});
    const std::size_t a = m2->add({"A", M::Kind::act, s, when(go)});
    const std::size_t g = m2->add({"G", M::Kind::maneuverGroup, a});
    const std::size_t mn = m2->add({"M", M::Kind::maneuver, g});
    const std::size_t e = m2->add({"E", M::Kind::event, mn});
    m = m2;
    EXPECT_FALSE(step(e));
    EXPECT_EQ(m->state(a), M::State::standby);
    go->on = true;
    EXPECT_TRUE(step(e)) << "the act starts and its event in the same step";
}

TEST_F(Machine, AnActsStopTriggerStopsItsEvents) {
    auto stop = std::make_shared<Switch>();
    auto m2 = std::make_shared<M>();
    const std::size_t sb = m2->add({"Storyboard", M::Kind::storyboard});
    const std::size_t s = m2->add({"S", M::Kind::story, sb});
    const std::size_t a = m2->add({"A", M::Kind::act, s, {}, when(stop)});
    const std::size_t g = m2->add({"G", M::Kind::maneuverGroup, a});
    const std::size_t mn = m2->add({"M", M::Kind::maneuver, g});
    auto never = std::make_shared<Switch>();
    const std::size_t e = m2->add({"E", M::Kind::event, mn, when(never)});
    m = m2;
    EXPECT_FALSE(step(e));
    EXPECT_EQ(m->state(a), M::State::running);
    stop->on = true;
    step(e);
    EXPECT_EQ(m->state(a), M::State::complete);
    EXPECT_TRUE(m->transitionedAt(a, M::Transition::stop, SimTime::fromSeconds(2)));
    never->on = true;
    EXPECT_FALSE(step(e)) << "its act is over";
}

TEST_F(Machine, TheStoryboardsStopTriggerEndsTheRunOnce) {
    auto stop = std::make_shared<Switch>();
    auto m2 = std::make_shared<M>();
    m2->add({"Storyboard", M::Kind::storyboard, std::nullopt, {}, when(stop)});
    m2->add({"S", M::Kind::story, 0});
    m = m2;
    int ended = 0;
    m->onEnd([&] { ++ended; });
    step(1);
    EXPECT_FALSE(m->ended());
    stop->on = true;
    step(1);
    step(1);
    EXPECT_TRUE(m->ended());
    EXPECT_EQ(ended, 1);
    EXPECT_EQ(m->state(0), M::State::complete);
    EXPECT_EQ(m->state(1), M::State::complete) << "the story is stopped with it";
}

TEST_F(Machine, StoryboardElementStateSeesAnotherEventsEnd) {
    auto sw = std::make_shared<Switch>();
    const std::size_t a = event("A", when(sw, M::Edge::rising));
    const std::size_t b =
        event("B", when(std::make_shared<ElementStateCondition>(m, a, std::nullopt, M::Transition::end)));
    const auto at = runs(b, 6, [&](int next) { sw->on = next >= 2; });
    EXPECT_EQ(at, (std::vector<int>{3})) << "A runs at 2, ends at 3; B, later in the storyboard, starts then";
    EXPECT_TRUE(ElementStateCondition(m, a, M::State::complete, std::nullopt).test(scene.ctx(), 0));
}

TEST_F(Machine, AdvancingTwiceInOneStepChangesNothing) {
    auto sw = std::make_shared<Switch>();
    sw->on = true;
    const std::size_t e = event("E", when(sw), 5);
    EXPECT_TRUE(step(e));
    m->advance(scene.ctx());
    EXPECT_EQ(m->executions(e), 1u);
}

TEST_F(Machine, ConditionsAreEvaluatedOnAWorldRowWhenNoVehicleRuns) {
    auto sw = std::make_shared<Switch>();
    sw->on = true;
    const std::size_t e =
        event("E", when(std::make_shared<EntityCondition>("a", std::make_shared<SpeedConditionGreater>(-1))));
    scene.set({}, SimTime::fromSeconds(++t));
    m->advance(scene.ctx());
    EXPECT_NE(m->state(e), M::State::running) << "no vehicle 'a'";
    EXPECT_TRUE(step(e));
}

TEST_F(Machine, TheStoryboardWaitsForItsStartTrigger) {
    auto ready = std::make_shared<Switch>();
    auto m2 = std::make_shared<M>();
    m2->add({"Storyboard", M::Kind::storyboard, std::nullopt, when(ready)});
    m2->add({"S", M::Kind::story, 0});
    const std::size_t a = m2->add({"A", M::Kind::act, 1});
    m = m2;
    EXPECT_FALSE(step(a));
    EXPECT_EQ(m->state(0), M::State::standby);
    ready->on = true;
    step(a);
    EXPECT_EQ(m->state(0), M::State::running);
    EXPECT_TRUE(m->transitionedAt(a, M::Transition::start, SimTime::fromSeconds(2)) ||
                m->transitionedAt(a, M::Transition::end, SimTime::fromSeconds(2)))
        << "the act started with it (and, having no maneuver group, ended at once)";
    EXPECT_EQ(m->executions(a), 1u);
}

TEST_F(Machine, AddRefusesWhatTheStandardDoesNotAllow) {
    auto sw = std::make_shared<Switch>();
    EXPECT_THROW(m->add({"E", M::Kind::event, act}), std::invalid_argument) << "an event's parent is a maneuver";
    EXPECT_THROW(m->add({"E", M::Kind::event, maneuver, {}, {}, 0}), std::invalid_argument);
    EXPECT_THROW(m->add({"G2", M::Kind::maneuverGroup, act, when(sw)}), std::invalid_argument);
    EXPECT_THROW(m->add({"E", M::Kind::event, maneuver, when(std::make_shared<SpeedConditionGreater>(1))}),
                 std::invalid_argument)
        << "a condition about an ego must be wrapped in an EntityCondition";
    EXPECT_THROW(m->add({"E", M::Kind::event, maneuver, when(sw, M::Edge::none, -1)}), std::invalid_argument);
    EXPECT_THROW(M().add({"S", M::Kind::story, std::nullopt}), std::invalid_argument);
}

TEST(EntityCondition, AsksAboutTheNamedVehicleWhateverTheEgo) {
    Scene scene{{car("a", 12), car("b", 3)}};
    EntityCondition fast("a", std::make_shared<SpeedConditionGreater>(10));
    EXPECT_TRUE(scene.test(fast, "b"));
    EXPECT_TRUE(scene.test(fast, "a"));
    EntityCondition gone("z", std::make_shared<SpeedConditionGreater>(0));
    EXPECT_FALSE(scene.test(gone, "a"));
    EXPECT_TRUE(fast.timeOnly());
    EXPECT_EQ(fast.describe(), "EntityCondition(a)");
    EXPECT_THROW(EntityCondition("", std::make_shared<SpeedConditionGreater>(0)), std::invalid_argument);
}

TEST_F(Machine, ElementConditionHoldsForTheActorsWhileTheElementRuns) {
    auto sw = std::make_shared<Switch>();
    const std::size_t e = event("E", when(sw, M::Edge::rising));
    ElementCondition forA(m, e, {"a"});
    ElementCondition world(m, act);
    scene.set({car("a", 0), car("b", 0)}, SimTime::fromSeconds(++t));
    forA.prepare(scene.ctx());
    EXPECT_FALSE(forA.test(scene.ctx(), scene.index("a")));
    EXPECT_TRUE(world.test(scene.ctx(), 0));
    sw->on = true;
    scene.set({car("a", 0), car("b", 0)}, SimTime::fromSeconds(++t));
    forA.prepare(scene.ctx());
    EXPECT_TRUE(forA.test(scene.ctx(), scene.index("a")));
    EXPECT_FALSE(forA.test(scene.ctx(), scene.index("b"))) << "not an actor";
    EXPECT_FALSE(forA.timeOnly());
    EXPECT_TRUE(world.timeOnly());
    EXPECT_EQ(forA.describe(), "ElementCondition(Event 'E', actors a; start (c rising))");
}

/// A storyboard whose act starts on `start` and whose one group runs `executions` times and may
/// select its act's triggering entities; the group's maneuver has one event without a trigger.
struct GroupMachine {
    GroupMachine(M::Trigger start, std::uint64_t executions, bool select) {
        const std::size_t board = m->add({"Storyboard", M::Kind::storyboard});
        const std::size_t story = m->add({"S", M::Kind::story, board});
        act = m->add({"A", M::Kind::act, story, std::move(start)});
        M::ElementSpec spec{"G", M::Kind::maneuverGroup, act};
        spec.maxExecutions = executions;
        spec.selectTriggeringEntities = select;
        group = m->add(spec);
        maneuver = m->add({"M", M::Kind::maneuver, group});
        event = m->add({"E", M::Kind::event, maneuver});
    }
    std::shared_ptr<M> m = std::make_shared<M>();
    std::size_t act, group, maneuver, event;
};

TEST_F(Machine, AManeuverGroupWithMaximumExecutionCountTwoRunsTwice) {
    GroupMachine g({}, 2, false);
    m = g.m;
    // The event runs at 1 and ends at 2 with its maneuver and group; the group, with one execution
    // left, is back in standby and starts again at 3 with its event new; at 4 it completes.
    EXPECT_EQ(runs(g.event, 6), (std::vector<int>{1, 3}));
    EXPECT_EQ(m->executions(g.group), 2u);
    EXPECT_EQ(m->executions(g.event), 1u) << "counted since its group last started";
    EXPECT_EQ(m->state(g.group), M::State::complete);
    EXPECT_EQ(m->state(g.act), M::State::complete);
}

TEST_F(Machine, ARestartedGroupsEventsWaitForTheirTriggersAgain) {
    GroupMachine g({}, 3, false);
    m = g.m;
    auto sw = std::make_shared<Switch>();
    const std::size_t e = m->add({"E2", M::Kind::event, g.maneuver, when(sw, M::Edge::rising)});
    // E2 fires on the rising edges at 2 and 6; the group ends once both events did (at 3 and 7)
    // and starts again at 4 and 8; its third round waits for an edge of E2 that never comes.
    const auto at = runs(e, 10, [&](int next) { sw->on = next == 2 || next == 6; });
    EXPECT_EQ(at, (std::vector<int>{2, 6}));
    EXPECT_EQ(m->executions(g.group), 3u);
    EXPECT_EQ(m->state(g.group), M::State::running);
    EXPECT_EQ(m->state(e), M::State::standby);
}

TEST(TriggeringEntitiesCondition, NamesTheEntitiesItHoldsFor) {
    Scene scene{{car("a", 12), car("b", 3), car("c", 15)}};
    const auto fast = [](const std::string& id) {
        return std::make_shared<EntityCondition>(id, std::make_shared<SpeedConditionGreater>(10));
    };
    TriggeringEntitiesCondition any({fast("c"), fast("b"), fast("a")}, false);
    const ConditionResult r = scene.test(any, "b");
    EXPECT_TRUE(r.isTrue());
    EXPECT_EQ(scene.others(r), (Ids{"a", "c"})) << "a and c are faster than 10 m/s, b is not";
    TriggeringEntitiesCondition all({fast("a"), fast("b")}, true);
    EXPECT_FALSE(scene.test(all, "a").isTrue());
    TriggeringEntitiesCondition both({fast("a"), fast("c")}, true);
    EXPECT_EQ(scene.others(scene.test(both, "b")), (Ids{"a", "c"}));
    EXPECT_TRUE(both.timeOnly());
    EXPECT_EQ(both.describe(), "TriggeringEntitiesCondition(all of a, c)");
    EXPECT_THROW(TriggeringEntitiesCondition({}, false), std::invalid_argument);
}

TEST_F(Machine, SelectTriggeringEntitiesMakesTheEntitiesThatStartedTheActActors) {
    const auto fast = [](const std::string& id) {
        return std::make_shared<EntityCondition>(id, std::make_shared<SpeedConditionGreater>(5));
    };
    auto trigger = std::make_shared<TriggeringEntitiesCondition>(
        std::vector<std::shared_ptr<EntityCondition>>{fast("a"), fast("b")}, false);
    GroupMachine g(when(trigger), 1, true);
    m = g.m;
    ElementCondition actors(m, g.event);
    EXPECT_FALSE(actors.timeOnly()) << "its actors are known only at run time";
    EXPECT_FALSE(step(g.event)) << "a stands, b stands: the act waits";
    speed = 8;  // a drives at 8 m/s from step 2 on, b still stands
    EXPECT_TRUE(step(g.event));
    EXPECT_EQ(m->triggeringEntities(g.act), (Ids{"a"}));
    EXPECT_EQ(m->selectedActors(g.event), (Ids{"a"}));
    EXPECT_TRUE(actors.test(scene.ctx(), scene.index("a")));
    EXPECT_FALSE(actors.test(scene.ctx(), scene.index("b"))) << "b did not trigger the act";
    EXPECT_NE(actors.describe().find("the entities that triggered its act"), std::string::npos);
    // A group that does not select keeps its own actors only.
    GroupMachine plain(when(trigger), 1, false);
    EXPECT_TRUE(plain.m->selectedActors(plain.event).empty());
    EXPECT_THROW(m->add({"E", M::Kind::event, g.maneuver, {}, {}, 1, M::Priority::parallel, true}),
                 std::invalid_argument)
        << "only a maneuver group selects triggering entities";
}

TEST_F(Machine, ADelayedConditionKeepsTheEntitiesItHeldFor) {
    const auto fast = std::make_shared<TriggeringEntitiesCondition>(
        std::vector<std::shared_ptr<EntityCondition>>{
            std::make_shared<EntityCondition>("a", std::make_shared<SpeedConditionGreater>(5))},
        false);
    GroupMachine g(when(fast, M::Edge::rising, 2), 1, true);
    m = g.m;
    speed = 8;
    EXPECT_FALSE(step(g.event));
    speed = 0;  // no longer true when the delay has run
    EXPECT_FALSE(step(g.event));
    EXPECT_TRUE(step(g.event)) << "seen 2 s after its rising edge at 1";
    EXPECT_EQ(m->triggeringEntities(g.act), (Ids{"a"}));
}

}  // namespace
}  // namespace sbsim::storyboard::test

namespace sbsim::storyboard::test {
namespace {

using R = ScenarioParameters::Rule;

TEST(ScenarioParameters, SetModifyAndCompare) {
    ScenarioParameters p;
    p.declare("Count", 0.0);
    p.declare("Mode", std::string("calm"));
    p.modify("Count", 2, false);
    p.modify("Count", 3, true);
    EXPECT_EQ(std::get<double>(p.get("Count")), 6.0);
    EXPECT_TRUE(p.compare("Count", R::greaterOrEqual, 6.0));
    EXPECT_FALSE(p.compare("Count", R::greaterThan, 6.0));
    p.set("Mode", std::string("storm"));
    EXPECT_TRUE(p.compare("Mode", R::equalTo, std::string("storm")));
    EXPECT_TRUE(p.compare("Mode", R::notEqualTo, 1.0)) << "a text is no number";
    EXPECT_FALSE(p.compare("Mode", R::equalTo, 1.0));
    EXPECT_THROW(p.set("Mode", 1.0), std::invalid_argument);
    EXPECT_THROW(p.modify("Mode", 1, false), std::invalid_argument);
    EXPECT_THROW(p.get("Nope"), std::out_of_range);
}

TEST(ParameterCondition, ReadsTheParameterAsItStandsNow) {
    auto p = std::make_shared<ScenarioParameters>();
    p->declare("Count", 0.0);
    ParameterCondition three(p, "Count", R::greaterOrEqual, 3.0);
    Scene scene{{car("a", 0)}};
    EXPECT_FALSE(scene.test(three, "a"));
    p->modify("Count", 3, false);
    EXPECT_TRUE(scene.test(three, "a"));
    EXPECT_TRUE(three.timeOnly());
    EXPECT_EQ(three.describe(), "ParameterCondition(Count >= 3)");
    EXPECT_THROW(ParameterCondition(p, "Nope", R::equalTo, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::storyboard::test
