// TrafficSignalCondition against a model of SUMO's traffic light states: the whole light or some
// links, letters by colour, one question per step, its errors, and a world story on a board that
// activates at the step the light turns red (and an OpenSCENARIO trigger with no vehicle running).

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "StoryboardTestSupport.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/storyboard/EventLog.h"
#include "sbsim/storyboard/ScenarioMachine.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/WorldStory.h"
#include "sbsim/storyboard/conditions/ElementCondition.h"
#include "sbsim/storyboard/conditions/TrafficSignalCondition.h"

namespace sbsim::storyboard::test {
namespace {

/// Traffic lights whose states the test sets; counts the questions.
class ModelLights : public traffic::TrafficQueries {
public:
    std::map<std::string, std::string> states;
    int asked = 0;

    std::optional<Leader> leader(const std::string&, double) override { return std::nullopt; }
    const std::vector<Collision>& collisions(SimTime) override { return none_; }
    std::optional<SignalPassage> signalPassage(const std::string&, const std::string&, const std::string&) override {
        return std::nullopt;
    }
    std::string signalState(const std::string& tls) override {
        ++asked;
        return states.at(tls);
    }

private:
    std::vector<Collision> none_;
};

/// One step at `t` s with the given vehicles, evaluated against `lights`.
struct LightScene {
    LightScene() { at(0); }
    void at(double t, std::vector<Vehicle> vehicles = {car("a", 10)}) {
        snapshot.assign(std::move(vehicles), SimTime::fromSeconds(t));
        grid.build(snapshot, 100);
    }
    bool test(Condition& c) {
        c.prepare(ctx);
        return c.test(ctx, 0).isTrue();
    }
    ModelLights lights;
    traffic::VehicleSnapshot snapshot;
    traffic::NeighbourGrid grid;
    EvaluationContext ctx{snapshot, grid, &lights};
};

TEST(TrafficSignalCondition, TheWholeLightComparesLetterByLetterByColour) {
    LightScene scene;
    scene.lights.states["J1"] = "GrGr";
    TrafficSignalCondition c("J1", "grgr");
    EXPECT_TRUE(scene.test(c)) << "G and g are both green";
    scene.at(1);
    scene.lights.states["J1"] = "yryr";
    EXPECT_FALSE(scene.test(c));
    EXPECT_TRUE(c.timeOnly());
    EXPECT_TRUE(c.pure()) << "it reads SUMO in prepare() only";
    EXPECT_EQ(c.columns(), traffic::SnapshotColumns{});
    EXPECT_EQ(c.describe(), "TrafficSignalCondition('J1' shows 'grgr')");
}

TEST(TrafficSignalCondition, LinksEachShowTheOneLetter) {
    LightScene scene;
    scene.lights.states["J1"] = "rGyO";
    TrafficSignalCondition red("J1", "r", {0});
    TrafficSignalCondition green("J1", "G", {1});
    TrafficSignalCondition yellow("J1", "Y", {2});
    TrafficSignalCondition off("J1", "o", {3});
    TrafficSignalCondition both("J1", "r", {0, 1});
    EXPECT_TRUE(scene.test(red));
    EXPECT_TRUE(scene.test(green));
    EXPECT_TRUE(scene.test(yellow)) << "y and Y are both yellow";
    EXPECT_TRUE(scene.test(off));
    EXPECT_FALSE(scene.test(both)) << "link 1 is green";
    EXPECT_EQ(both.describe(), "TrafficSignalCondition('J1' links 0,1 show 'r')");
    EXPECT_EQ(red.describe(), "TrafficSignalCondition('J1' link 0 shows 'r')");
    TrafficSignalCondition redYellow("J1", "u", {0});
    EXPECT_FALSE(scene.test(redYellow)) << "red-yellow is not red";
}

TEST(TrafficSignalCondition, AsksSumoOncePerStepHoweverOftenItIsTested) {
    LightScene scene;
    scene.lights.states["J1"] = "rr";
    TrafficSignalCondition c("J1", "rr");
    scene.at(1, {car("a", 10), car("b", 10), car("c", 10)});
    c.prepare(scene.ctx);
    for (VehicleIndex i = 0; i < 3; ++i) EXPECT_TRUE(c.test(scene.ctx, i));
    EXPECT_EQ(scene.lights.asked, 1);
    scene.lights.states["J1"] = "GG";
    EXPECT_TRUE(c.test(scene.ctx, 0)) << "the same step: what prepare() read";
    scene.at(2);
    EXPECT_FALSE(c.test(scene.ctx, 0)) << "unprepared, a new step reads again";
    EXPECT_EQ(scene.lights.asked, 2);
}

TEST(TrafficSignalCondition, Errors) {
    EXPECT_THROW(TrafficSignalCondition("", "r"), std::invalid_argument);
    EXPECT_THROW(TrafficSignalCondition("J1", ""), std::invalid_argument);
    EXPECT_THROW(TrafficSignalCondition("J1", "rx"), std::invalid_argument);
    EXPECT_THROW(TrafficSignalCondition("J1", "rr", {0}), std::invalid_argument) << "links take one letter";
    EXPECT_THROW(TrafficSignalCondition("J1", "r", {-1}), std::invalid_argument);
    LightScene scene;
    scene.lights.states["J1"] = "rGr";
    TrafficSignalCondition longer("J1", "rrrr");
    try {
        scene.test(longer);
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "TrafficSignalCondition: the state 'rrrr' has 4 signals, traffic light 'J1' controls 3");
    }
    TrafficSignalCondition beyond("J1", "r", {3});
    try {
        scene.test(beyond);
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "TrafficSignalCondition: traffic light 'J1' has no link 3 (it controls 3)");
    }
}

/// A board whose traffic is `ModelLights`, stepped with no vehicle running.
class SignalBoard : public testing::Test {
protected:
    SignalBoard() : log(out), board(sim.emplaceModule<Storyboard>(registry, &log)) {
        auto model = std::make_unique<ModelLights>();
        lights = model.get();
        board.setTrafficQueries(std::move(model));
    }
    void step(double t) {
        snapshot.assign({}, SimTime::fromSeconds(t));
        board.update(snapshot, {});
    }

    std::ostringstream out;
    EventLog log;
    traffic::VehicleRegistry registry;
    kernel::Simulation sim{7};
    Storyboard& board;
    ModelLights* lights = nullptr;
    traffic::VehicleSnapshot snapshot;
};

TEST_F(SignalBoard, AWorldStoryIsActiveFromTheStepTheLinkTurnsRed) {
    board.registerStory(
        std::make_shared<WorldStory>(std::make_shared<TrafficSignalCondition>("J1", "r", std::vector<int>{1}),
                                     std::vector<WorldEffectPtr>{}, "red"));
    const std::vector<std::string> program{"GGrr", "GGrr", "yyrr", "rrGG", "rrGG", "rryy", "GGrr"};
    for (std::size_t t = 0; t < program.size(); ++t) {
        lights->states["J1"] = program[t];
        step(static_cast<double>(t));
    }
    log.flush();
    const std::string events = out.str();
    EXPECT_NE(events.find("\"t\":3,\"type\":\"activate\",\"story\":\"red\""), std::string::npos) << events;
    EXPECT_NE(events.find("\"t\":6,\"type\":\"deactivate\",\"story\":\"red\""), std::string::npos) << events;
    EXPECT_EQ(lights->asked, 7) << "once per step";
}

TEST_F(SignalBoard, AnOpenScenarioTriggerReadsTheLightWithNoVehicleRunning) {
    auto machine = std::make_shared<ScenarioMachine>();
    const std::size_t sb = machine->add({"Storyboard", ScenarioMachine::Kind::storyboard});
    const std::size_t story = machine->add({"S", ScenarioMachine::Kind::story, sb});
    ScenarioMachine::Trigger red{
        {{"red", std::make_shared<TrafficSignalCondition>("J1", "rr"), ScenarioMachine::Edge::rising, 0}}};
    const std::size_t act = machine->add({"A", ScenarioMachine::Kind::act, story, red});
    board.registerStory(std::make_shared<WorldStory>(std::make_shared<ElementCondition>(machine, act),
                                                     std::vector<WorldEffectPtr>{}, "S/A"));
    lights->states["J1"] = "GG";
    step(0);
    step(1);
    EXPECT_EQ(machine->executions(act), 0u);
    lights->states["J1"] = "rr";
    step(2);
    EXPECT_EQ(machine->executions(act), 1u) << "started at the step the light turned red";
}

}  // namespace
}  // namespace sbsim::storyboard::test
