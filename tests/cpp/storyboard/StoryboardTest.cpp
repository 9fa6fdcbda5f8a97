// The board's evaluation pass on hand-made snapshots: event order (vehicle_left first, then
// vehicles by id, stories by registration), activation/deactivation, signals, effect removal,
// and that nothing lingers after a vehicle leaves.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "StoryboardTestSupport.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/storyboard/EventLog.h"
#include "sbsim/storyboard/ScenarioMachine.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/VehicleHandle.h"
#include "sbsim/storyboard/WorldStory.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/CarSetCondition.h"
#include "sbsim/storyboard/conditions/ElementCondition.h"
#include "sbsim/storyboard/conditions/LimitCondition.h"
#include "sbsim/storyboard/conditions/PolygonCondition.h"
#include "sbsim/storyboard/conditions/RisingCondition.h"
#include "sbsim/storyboard/conditions/SpeedCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/conditions/TtcCondition.h"
#include "sbsim/storyboard/effects/LaneEffect.h"
#include "sbsim/storyboard/effects/SignalEffect.h"
#include "sbsim/storyboard/effects/SpeedChangeEffect.h"
#include "sbsim/storyboard/effects/SpeedEffect.h"
#include "sbsim/storyboard/effects/StopEffect.h"
#include "sbsim/traffic/StoryboardSignal.h"

namespace sbsim::storyboard {
namespace {

using kernel::SimTime;
using traffic::StoryboardSignal;
using traffic::VehicleSnapshot;

/// Records every command per vehicle; max speed starts at 50.
struct Commands {
    std::map<std::string, double> maxSpeed;
    std::map<std::string, std::vector<double>> setSpeed;
    std::map<std::string, std::vector<std::pair<int, double>>> changeLane;  // index, seconds
};

class RecordingVehicle : public traffic::VehicleController {
public:
    RecordingVehicle(const std::string& id, Commands& log) : VehicleController(id), log_(log) {
        log_.maxSpeed.try_emplace(id, 50.0);
    }
    double maxSpeed() const override { return log_.maxSpeed.at(id()); }
    double speed() const override { return 10.0; }
    int speedMode() const override { return 31; }
    double emergencyDecel() const override { return 9.0; }
    void setMaxSpeed(double mps) override { log_.maxSpeed[id()] = mps; }
    void setSpeed(double mps) override { log_.setSpeed[id()].push_back(mps); }
    std::string roadId() const override { return "road"; }
    int laneCount() const override { return 2; }
    int laneIndex() const override { return 0; }
    void changeLane(int index, double seconds) override { log_.changeLane[id()].emplace_back(index, seconds); }

private:
    Commands& log_;
};

using test::car;

class SignalProbe : public kernel::Listener {
public:
    void receiveSignal(kernel::Module&, kernel::SignalId, const kernel::Object& value) override {
        signals.push_back(dynamic_cast<const traffic::StoryboardSignal&>(value));
    }
    std::vector<traffic::StoryboardSignal> signals;
};

class StoryboardTest : public testing::Test {
protected:
    StoryboardTest() : log(out), board(sim.emplaceModule<Storyboard>(registry, &log)) {
        registry.setControllerFactory(
            [this](const std::string& id) { return std::make_unique<RecordingVehicle>(id, commands); });
        sim.subscribe(traffic::StoryboardSignal::id, probe);
    }

    void step(double t, std::vector<VehicleSnapshot::Vehicle> vehicles, std::vector<std::string> left = {}) {
        snapshot.assign(std::move(vehicles), SimTime::fromSeconds(t));
        board.update(snapshot, std::move(left));
    }

    std::vector<std::string> lines() {
        std::vector<std::string> out;
        std::istringstream in(this->out.str());
        for (std::string line; std::getline(in, line);) out.push_back(line);
        this->out.str("");
        return out;
    }

    std::ostringstream out;
    EventLog log;
    traffic::VehicleRegistry registry;
    kernel::Simulation sim{7};
    Storyboard& board;
    Commands commands;
    SignalProbe probe;
    VehicleSnapshot snapshot;
};

TEST_F(StoryboardTest, ActivatesByVehicleIdThenStoryOrderAndNamesUnnamedStories) {
    board.registerStory(std::make_shared<Story>(std::make_shared<SpeedConditionGreater>(5.0),
                                                std::vector<EffectPtr>{std::make_shared<SpeedEffect>(3.0)}, "fast"));
    board.registerStory(std::make_shared<Story>(std::make_shared<SpeedConditionLess>(100.0), std::vector<EffectPtr>{}));
    step(1, {car("b", 10), car("a", 10), car("B", 1)});
    EXPECT_EQ(lines(), (std::vector<std::string>{
                           R"({"t":1,"type":"activate","story":"story1","vehicle":"B"})",
                           R"({"t":1,"type":"activate","story":"fast","vehicle":"a"})",
                           R"({"t":1,"type":"activate","story":"story1","vehicle":"a"})",
                           R"({"t":1,"type":"activate","story":"fast","vehicle":"b"})",
                           R"({"t":1,"type":"activate","story":"story1","vehicle":"b"})",
                       }));
    EXPECT_DOUBLE_EQ(commands.maxSpeed.at("a"), 3.0);
    EXPECT_EQ(board.stories()[0]->counters().activations(), 2u);
}

TEST_F(StoryboardTest, DeactivatesWhenTheConditionTurnsFalseAndRestores) {
    board.registerStory(std::make_shared<Story>(std::make_shared<SpeedConditionGreater>(5.0),
                                                std::vector<EffectPtr>{std::make_shared<SpeedEffect>(3.0)}, "fast"));
    step(1, {car("a", 10)});
    step(2, {car("a", 4)});
    EXPECT_EQ(lines().back(), R"({"t":2,"type":"deactivate","story":"fast","vehicle":"a","reason":"condition"})");
    EXPECT_DOUBLE_EQ(commands.maxSpeed.at("a"), 50.0);
    EXPECT_FALSE(board.isActive("a", *board.stories()[0]));
}

TEST_F(StoryboardTest, VehiclesThatLeftAreDeactivatedFirstWithoutCommands) {
    board.registerStory(std::make_shared<Story>(std::make_shared<SpeedConditionGreater>(5.0),
                                                std::vector<EffectPtr>{std::make_shared<StopEffect>()}, "s1"));
    board.registerStory(std::make_shared<Story>(std::make_shared<SpeedConditionGreater>(6.0),
                                                std::vector<EffectPtr>{std::make_shared<StopEffect>()}, "s2"));
    step(1, {car("x", 10), car("y", 10)});
    lines();
    const auto stopsBefore = commands.setSpeed.at("y").size();
    step(2, {car("a", 10)}, {"y", "x"});
    EXPECT_EQ(lines(), (std::vector<std::string>{
                           R"({"t":2,"type":"deactivate","story":"s1","vehicle":"x","reason":"vehicle_left"})",
                           R"({"t":2,"type":"deactivate","story":"s2","vehicle":"x","reason":"vehicle_left"})",
                           R"({"t":2,"type":"deactivate","story":"s1","vehicle":"y","reason":"vehicle_left"})",
                           R"({"t":2,"type":"deactivate","story":"s2","vehicle":"y","reason":"vehicle_left"})",
                           R"({"t":2,"type":"activate","story":"s1","vehicle":"a"})",
                           R"({"t":2,"type":"activate","story":"s2","vehicle":"a"})",
                       }));
    EXPECT_EQ(commands.setSpeed.at("y").size(), stopsBefore) << "no SUMO command for a vehicle that left";
    EXPECT_FALSE(board.isActive("x", *board.stories()[0]));
}

/// A RecordingVehicle a speed transition may command (its step length, its speed mode).
class TransitionVehicle : public RecordingVehicle {
public:
    using RecordingVehicle::RecordingVehicle;
    double stepLength() const override { return 1.0; }
    void setSpeedMode(int /*mode*/) override {}
};

TEST_F(StoryboardTest, AnEventWhoseActorLeftMidTransitionEnds) {
    registry.setControllerFactory(
        [this](const std::string& id) { return std::make_unique<TransitionVehicle>(id, commands); });
    using M = ScenarioMachine;
    auto m = std::make_shared<M>();
    m->add({"Storyboard", M::Kind::storyboard});
    m->add({"S", M::Kind::story, 0});
    const std::size_t act = m->add({"A", M::Kind::act, 1});
    m->add({"G", M::Kind::maneuverGroup, act});
    m->add({"M", M::Kind::maneuver, 3});
    const std::size_t event = m->add({"E", M::Kind::event, 4});
    // From 10 to 30 m/s over 100 s: far from its target when "a" leaves at t = 3.
    auto change = std::make_shared<SpeedChangeEffect>(
        30, traffic::Transition{traffic::Transition::Shape::Linear, traffic::Transition::Dimension::Time, 100});
    m->addAction(event, change);
    board.registerStory(std::make_shared<WorldStory>(std::make_shared<ElementCondition>(m, 0),
                                                     std::vector<WorldEffectPtr>{}, "Storyboard"));
    board.registerStory(
        std::make_shared<Story>(std::make_shared<ElementCondition>(m, event, std::set<std::string>{"a"}),
                                std::vector<EffectPtr>{change}, "S/A/E"));
    step(1, {car("a", 10), car("b", 10)});
    step(2, {car("a", 11), car("b", 10)});
    EXPECT_EQ(m->state(event), M::State::running);
    EXPECT_FALSE(change->complete());
    step(3, {car("b", 10)}, {"a"});
    EXPECT_TRUE(change->complete()) << "the activation of a vehicle that left is forgotten";
    EXPECT_EQ(m->state(event), M::State::complete) << "its event ends at the step its actor left";
    EXPECT_TRUE(m->transitionedAt(event, M::Transition::end, SimTime::fromSeconds(3)));
}

TEST_F(StoryboardTest, SignalComesRightAfterItsActivationWithSortedOthers) {
    // A condition whose result is a set of other vehicles: ego's id in {"c"} ∧ "all others slower than 100".
    class OthersCondition : public Condition {
    public:
        ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override {
            std::vector<VehicleIndex> others;
            for (VehicleIndex i = 0; i < ctx.snapshot().size(); ++i) {
                if (i != ego) others.push_back(i);
            }
            return ConditionResult::ofOthers(std::move(others));
        }
    };
    board.registerStory(std::make_shared<Story>(
        std::make_shared<AndCondition>(std::make_shared<CarSetCondition>(std::set<std::string>{"c"}),
                                       std::make_shared<OthersCondition>()),
        std::vector<EffectPtr>{std::make_shared<SignalEffect>("siren on")}, "siren"));
    step(3, {car("z", 1), car("c", 1), car("a", 1)});
    EXPECT_EQ(lines(),
              (std::vector<std::string>{
                  R"({"t":3,"type":"activate","story":"siren","vehicle":"c"})",
                  R"({"t":3,"type":"signal","story":"siren","vehicle":"c","cause":"siren on","others":["a","z"]})",
              }));
    ASSERT_EQ(probe.signals.size(), 1u);
    EXPECT_EQ(probe.signals[0].ego, "c");
    EXPECT_EQ(probe.signals[0].story, "siren");
    EXPECT_EQ(probe.signals[0].others, (std::vector<std::string>{"a", "z"}));
    step(4, {car("z", 1), car("c", 1), car("a", 1)});
    EXPECT_EQ(probe.signals.size(), 1u) << "a signal goes out once, when the story activates";
}

TEST_F(StoryboardTest, SharedLimitConditionKeepsItsStateAcrossStories) {
    const auto limit = std::make_shared<LimitCondition>(2);
    board.registerStory(std::make_shared<Story>(limit, std::vector<EffectPtr>{}, "first"));
    board.registerStory(std::make_shared<Story>(limit, std::vector<EffectPtr>{}, "second"));
    step(1, {car("a", 1), car("b", 1), car("c", 1)});
    const auto events = lines();
    EXPECT_EQ(events.size(), 4u);  // a and b, each in both stories; c never
    for (const std::string& e : events) EXPECT_EQ(e.find("\"c\""), std::string::npos) << e;
}

TEST_F(StoryboardTest, TwoStopStoriesHoldUntilTheLastEnds) {
    board.registerStory(
        std::make_shared<Story>(std::make_shared<TimeCondition>(SimTime::fromSeconds(1), SimTime::fromSeconds(3)),
                                std::vector<EffectPtr>{std::make_shared<StopEffect>()}, "early"));
    board.registerStory(
        std::make_shared<Story>(std::make_shared<TimeCondition>(SimTime::fromSeconds(2), SimTime::fromSeconds(5)),
                                std::vector<EffectPtr>{std::make_shared<StopEffect>()}, "late"));
    for (int t = 1; t <= 6; ++t) step(t, {car("a", 1)});
    // Held once at t=1 (0), released once at t=6 (-1): the first story ending at t=4 sends nothing.
    EXPECT_EQ(commands.setSpeed.at("a"), (std::vector<double>{0.0, -1.0}));
}

TEST_F(StoryboardTest, ALaneIsRenewedEachStepWhileItsStoryIsActiveOnly) {
    board.registerStory(
        std::make_shared<Story>(std::make_shared<TimeCondition>(SimTime::fromSeconds(2), SimTime::fromSeconds(3)),
                                std::vector<EffectPtr>{std::make_shared<LaneEffect>(1)}, "keep left"));
    for (int t = 1; t <= 6; ++t) step(t, {car("a", 10), car("b", 10)});
    const double hold = traffic::EffectStack::kLaneHoldSeconds;
    // t=2: the activation's command and the step's renewal; t=3: renewed; t=4: released; then nothing.
    EXPECT_EQ(commands.changeLane.at("a"),
              (std::vector<std::pair<int, double>>{{1, hold}, {1, hold}, {1, hold}, {0, 0.0}}));
    EXPECT_EQ(commands.changeLane.at("b").size(), 4U);
}

TEST_F(StoryboardTest, AVehicleMissingFromOneSnapshotKeepsItsStories) {
    // The board carries each vehicle's stories from one pass to the next by id; a vehicle absent
    // from one snapshot (without leaving) must come back with its stories still active.
    board.registerStory(std::make_shared<Story>(std::make_shared<SpeedConditionGreater>(5.0),
                                                std::vector<EffectPtr>{std::make_shared<StopEffect>()}, "fast"));
    step(1, {car("a", 10), car("b", 10)});
    step(2, {car("b", 10)});
    step(3, {car("a", 10), car("b", 10)});
    const auto events = lines();
    EXPECT_EQ(events.size(), 2u) << "activated once each, never again";
    EXPECT_TRUE(board.isActive("a", *board.stories()[0]));
    EXPECT_EQ(commands.setSpeed.at("a"), (std::vector<double>{0.0}));
    step(4, {car("a", 1), car("b", 10)});
    EXPECT_EQ(
        lines(),
        (std::vector<std::string>{R"({"t":4,"type":"deactivate","story":"fast","vehicle":"a","reason":"condition"})"}));
    EXPECT_EQ(commands.setSpeed.at("a"), (std::vector<double>{0.0, -1.0}));
}

TEST_F(StoryboardTest, RowsFollowTheirVehiclesWhetherOrNotOthersCameOrWent) {
    // While the same vehicles run (the snapshot's idsVersion() unchanged) each vehicle's row stays
    // at its index; once one came or went the rows are matched by id. A row read at the wrong
    // index would (de)activate the wrong vehicle.
    board.registerStory(std::make_shared<Story>(std::make_shared<SpeedConditionGreater>(5.0),
                                                std::vector<EffectPtr>{std::make_shared<StopEffect>()}, "fast"));
    step(1, {car("a", 1), car("b", 1), car("c", 10)});
    const std::uint64_t version = snapshot.idsVersion();
    step(2, {car("a", 1), car("b", 10), car("c", 10)});
    ASSERT_EQ(snapshot.idsVersion(), version) << "the same vehicles: rows kept in place";
    step(3, {car("a", 1), car("c", 10)}, {"b"});  // b left: c moves from index 2 to 1
    ASSERT_NE(snapshot.idsVersion(), version);
    step(4, {car("a", 1), car("c", 10)});
    step(5, {car("a", 10), car("c", 1)});
    step(6, {car("0", 1), car("a", 10), car("c", 1)});         // one came before them: both move up
    step(7, {car("a", 10), car("c", 1), car("e", 1)}, {"0"});  // as many, all moved down: a at 0
    EXPECT_EQ(lines(), (std::vector<std::string>{
                           R"({"t":1,"type":"activate","story":"fast","vehicle":"c"})",
                           R"({"t":2,"type":"activate","story":"fast","vehicle":"b"})",
                           R"({"t":3,"type":"deactivate","story":"fast","vehicle":"b","reason":"vehicle_left"})",
                           R"({"t":5,"type":"activate","story":"fast","vehicle":"a"})",
                           R"({"t":5,"type":"deactivate","story":"fast","vehicle":"c","reason":"condition"})",
                       }));
    EXPECT_TRUE(board.isActive("a", *board.stories()[0]));
    EXPECT_FALSE(board.isActive("c", *board.stories()[0]));
}

TEST_F(StoryboardTest, AVehicleReportedLeftWhileStillInTheSnapshotStartsAfresh) {
    // Its state is dropped (vehicle_left) although the same vehicles run on: its row, kept in
    // place, must not still say "active" (the pass would then deactivate a state it no longer has).
    board.registerStory(std::make_shared<Story>(std::make_shared<SpeedConditionGreater>(5.0),
                                                std::vector<EffectPtr>{std::make_shared<StopEffect>()}, "fast"));
    step(1, {car("a", 10), car("b", 10)});
    step(2, {car("a", 10), car("b", 10)}, {"a"});
    step(3, {car("a", 1), car("b", 1)});
    EXPECT_EQ(lines(), (std::vector<std::string>{
                           R"({"t":1,"type":"activate","story":"fast","vehicle":"a"})",
                           R"({"t":1,"type":"activate","story":"fast","vehicle":"b"})",
                           R"({"t":2,"type":"deactivate","story":"fast","vehicle":"a","reason":"vehicle_left"})",
                           R"({"t":2,"type":"activate","story":"fast","vehicle":"a"})",
                           R"({"t":3,"type":"deactivate","story":"fast","vehicle":"a","reason":"condition"})",
                           R"({"t":3,"type":"deactivate","story":"fast","vehicle":"b","reason":"condition"})",
                       }));
}

TEST_F(StoryboardTest, AStoryRegisteredBetweenPassesJoinsTheNextOne) {
    board.registerStory(
        std::make_shared<Story>(std::make_shared<SpeedConditionGreater>(5.0), std::vector<EffectPtr>{}, "fast"));
    step(1, {car("a", 10), car("b", 1)});
    board.registerStory(
        std::make_shared<Story>(std::make_shared<SpeedConditionLess>(5.0), std::vector<EffectPtr>{}, "slow"));
    step(2, {car("a", 10), car("b", 1)});
    step(3, {car("a", 1), car("b", 1)});
    EXPECT_EQ(lines(), (std::vector<std::string>{
                           R"({"t":1,"type":"activate","story":"fast","vehicle":"a"})",
                           R"({"t":2,"type":"activate","story":"slow","vehicle":"b"})",
                           R"({"t":3,"type":"deactivate","story":"fast","vehicle":"a","reason":"condition"})",
                           R"({"t":3,"type":"activate","story":"slow","vehicle":"a"})",
                       }));
}

TEST_F(StoryboardTest, ARisingStoryIsActiveForExactlyOneStep) {
    board.registerStory(
        std::make_shared<Story>(std::make_shared<RisingCondition>(std::make_shared<SpeedConditionGreater>(5.0)),
                                std::vector<EffectPtr>{std::make_shared<SpeedEffect>(3.0)}, "rise"));
    step(1, {car("a", 1)});
    step(2, {car("a", 10)});
    EXPECT_DOUBLE_EQ(commands.maxSpeed.at("a"), 3.0);
    step(3, {car("a", 10)});
    EXPECT_DOUBLE_EQ(commands.maxSpeed.at("a"), 50.0);
    step(4, {car("a", 10)});
    step(5, {car("a", 1)});
    step(6, {car("a", 10)});
    EXPECT_EQ(lines(), (std::vector<std::string>{
                           R"({"t":2,"type":"activate","story":"rise","vehicle":"a"})",
                           R"({"t":3,"type":"deactivate","story":"rise","vehicle":"a","reason":"condition"})",
                           R"({"t":6,"type":"activate","story":"rise","vehicle":"a"})",
                       }));
}

TEST_F(StoryboardTest, MaxActivationsLimitsEachVehicleUntilItLeaves) {
    board.registerStory(std::make_shared<Story>(std::make_shared<SpeedConditionGreater>(5.0),
                                                std::vector<EffectPtr>{std::make_shared<SpeedEffect>(3.0)}, "twice",
                                                2));
    board.registerStory(
        std::make_shared<Story>(std::make_shared<SpeedConditionGreater>(5.0), std::vector<EffectPtr>{}, "unlimited"));
    // a flips fast/slow every step; b is fast throughout.
    for (int t = 1; t <= 8; ++t) step(t, {car("a", t % 2 == 1 ? 10 : 1), car("b", 10)});
    EXPECT_EQ(board.stories()[0]->counters().activations(), 3u) << "a twice, b once";
    EXPECT_EQ(board.stories()[1]->counters().activations(), 5u) << "a at t = 1, 3, 5, 7; b once";
    EXPECT_FALSE(board.isActive("a", *board.stories()[0]));
    EXPECT_DOUBLE_EQ(commands.maxSpeed.at("a"), 50.0) << "the last activation ended and was not renewed";
    lines();
    // A vehicle that left and comes back under the same id starts afresh.
    step(9, {car("b", 10)}, {"a"});
    step(10, {car("a", 10), car("b", 10)});
    EXPECT_EQ(lines(), (std::vector<std::string>{
                           R"({"t":10,"type":"activate","story":"twice","vehicle":"a"})",
                           R"({"t":10,"type":"activate","story":"unlimited","vehicle":"a"})",
                       }));
}

TEST(StoryboardPurity, TreesArePureOnlyWithoutStatefulNodes) {
    const auto time = std::make_shared<TimeCondition>(SimTime::fromSeconds(1), std::nullopt);
    const auto fast = std::make_shared<SpeedConditionGreater>(5.0);
    EXPECT_TRUE(AndCondition(time, fast).pure());
    EXPECT_FALSE(AndCondition(time, std::make_shared<LimitCondition>(3)).pure());
    EXPECT_FALSE(AndCondition(std::make_shared<LimitCondition>(3), fast).pure());
}

/// Every event of a run over many vehicles and steps, with `threads` evaluating the pure stories.
std::string runWithThreads(unsigned threads) {
    std::ostringstream out;
    EventLog log(out);
    traffic::VehicleRegistry registry;
    kernel::Simulation sim(7, threads);
    auto& board = sim.emplaceModule<Storyboard>(registry, &log);
    Commands commands;
    registry.setControllerFactory(
        [&](const std::string& id) { return std::make_unique<RecordingVehicle>(id, commands); });
    // Pure stories (evaluated in parallel) between impure ones (a Limit shared by two stories).
    const auto limit = std::make_shared<LimitCondition>(40);
    board.registerStory(
        std::make_shared<Story>(std::make_shared<AndCondition>(std::make_shared<SpeedConditionGreater>(7.0), limit),
                                std::vector<EffectPtr>{std::make_shared<SpeedEffect>(3.0)}, "first fast"));
    board.registerStory(std::make_shared<Story>(std::make_shared<SpeedConditionLess>(4.0),
                                                std::vector<EffectPtr>{std::make_shared<StopEffect>()}, "slow"));
    board.registerStory(std::make_shared<Story>(
        std::make_shared<AndCondition>(std::make_shared<TimeCondition>(SimTime::fromSeconds(3), std::nullopt), limit),
        std::vector<EffectPtr>{std::make_shared<SignalEffect>("late")}, "late"));
    VehicleSnapshot snapshot;
    for (int t = 1; t <= 8; ++t) {
        std::vector<VehicleSnapshot::Vehicle> vehicles;
        for (int v = 0; v < 3000; ++v) {
            if ((v + t) % 11 == 0) continue;  // vehicles come and go
            vehicles.push_back(car("v" + std::to_string(v), (v * 7 + t * 3) % 13));
        }
        snapshot.assign(std::move(vehicles), SimTime::fromSeconds(t));
        board.update(snapshot, {});
    }
    return out.str();
}

TEST(StoryboardParallel, ThreadsChangeNothingButTheTime) {
    const std::string one = runWithThreads(1);
    EXPECT_GT(std::count(one.begin(), one.end(), '\n'), 1000);
    EXPECT_EQ(runWithThreads(2), one);
    EXPECT_EQ(runWithThreads(4), one);
}

/// Keeps the handle of every vehicle it is applied to, as a script may.
class KeepingEffect : public Effect {
public:
    void apply(EffectScope& scope) override { kept.push_back(scope.handle()); }
    void remove(EffectScope&) override {}
    std::vector<VehicleHandle> kept;
};

TEST_F(StoryboardTest, KeptHandleOfAVehicleThatLeftThrowsInsteadOfDangling) {
    auto keeping = std::make_shared<KeepingEffect>();
    board.registerStory(
        std::make_shared<Story>(std::make_shared<SpeedConditionGreater>(5.0), std::vector<EffectPtr>{keeping}, "keep"));
    step(1, {car("x", 10), car("y", 10)});
    ASSERT_EQ(keeping->kept.size(), 2u);
    VehicleHandle& x = keeping->kept[0];
    x.setMaxSpeed(12.0);
    EXPECT_EQ(commands.maxSpeed.at("x"), 12.0);
    step(2, {car("y", 10)}, {"x"});
    EXPECT_FALSE(x.alive());
    EXPECT_TRUE(keeping->kept[1].alive());
    try {
        x.setMaxSpeed(3.0);
        FAIL() << "a handle of a vehicle that left must throw";
    } catch (const VehicleGone& e) {
        EXPECT_STREQ(e.what(), "vehicle 'x' has left the simulation; its VehicleController can no longer be used");
    }
    EXPECT_THROW((void)x.speed(), VehicleGone);
    EXPECT_EQ(commands.maxSpeed.at("x"), 12.0);
}

TEST_F(StoryboardTest, HandleRefusesValuesSumoCannotTake) {
    auto keeping = std::make_shared<KeepingEffect>();
    board.registerStory(
        std::make_shared<Story>(std::make_shared<SpeedConditionGreater>(5.0), std::vector<EffectPtr>{keeping}, "keep"));
    step(1, {car("x", 10)});
    VehicleHandle& x = keeping->kept.at(0);
    EXPECT_THROW(x.setMaxSpeed(std::nan("")), std::invalid_argument);
    EXPECT_THROW(x.setMaxSpeed(-1.0), std::invalid_argument);
    EXPECT_THROW(x.slowDown(5.0, -10.0), std::invalid_argument);
    EXPECT_THROW(x.slowDown(INFINITY, 1.0), std::invalid_argument);
    EXPECT_THROW(x.setSpeed(std::nan("")), std::invalid_argument);
    EXPECT_THROW(x.changeLane(-1, 1.0), std::invalid_argument);
    EXPECT_EQ(commands.maxSpeed.at("x"), 50.0) << "nothing reached the vehicle";
    x.setSpeed(-1.0);  // hands control back to SUMO, as in libsumo
    EXPECT_EQ(commands.setSpeed.at("x").back(), -1.0);
}

TEST_F(StoryboardTest, ActiveVehicleSecondsSumTheTimeVehiclesSpendUnderAStory) {
    board.registerStory(
        std::make_shared<Story>(std::make_shared<SpeedConditionGreater>(5.0), std::vector<EffectPtr>{}, "fast"));
    const Story& fast = *board.stories()[0];
    step(1, {car("a", 10), car("b", 1)});
    EXPECT_EQ(fast.counters().activeVehicles(), 1u);
    step(2, {car("a", 10), car("b", 10)});  // a: 1 s so far; b joins
    EXPECT_DOUBLE_EQ(fast.counters().activeVehicleSeconds(), 1.0);
    step(2.5, {car("a", 1), car("b", 10)});  // both active for 0.5 s, then a stops being fast
    EXPECT_DOUBLE_EQ(fast.counters().activeVehicleSeconds(), 2.0);
    EXPECT_EQ(fast.counters().activeVehicles(), 1u);
    step(4, {car("a", 1)}, {"b"});  // b was active until it left
    EXPECT_DOUBLE_EQ(fast.counters().activeVehicleSeconds(), 3.5);
    EXPECT_EQ(fast.counters().activeVehicles(), 0u);
    step(9, {car("a", 1)});
    EXPECT_DOUBLE_EQ(fast.counters().activeVehicleSeconds(), 3.5);
    EXPECT_EQ(fast.counters().activations(), 2u);
}

// What the snapshot must read is what the trees' nodes declare (plus speed for the stacks that
// hold a vehicle): a board with a time window and an area needs positions, not lanes or angles.
TEST_F(StoryboardTest, ColumnsAreTheUnionOfWhatTheNodesRead) {
    using Col = traffic::SnapshotColumns;
    EXPECT_TRUE(board.columns().empty()) << "no story: nothing to read";
    const auto area =
        std::make_shared<PolygonCondition>(std::vector<Eigen::Vector2d>{{0, 0}, {10, 0}, {10, 10}, {0, 10}});
    board.registerStory(std::make_shared<Story>(
        std::make_shared<AndCondition>(
            area, std::make_shared<TimeCondition>(SimTime::fromSeconds(1), SimTime::fromSeconds(2))),
        std::vector<EffectPtr>{}, "rain"));
    EXPECT_EQ(board.columns(), (Col{Col::Position, Col::Speed})) << board.columns().str();
    board.registerStory(std::make_shared<Story>(std::make_shared<TtcCondition>(2.0, 50.0), std::vector<EffectPtr>{}));
    EXPECT_EQ(board.columns(), (Col{Col::Position, Col::Speed, Col::Angle, Col::Size})) << board.columns().str();
    EXPECT_FALSE(board.columns().contains(Col::Lane));
}

}  // namespace
}  // namespace sbsim::storyboard
