// World stories on a model network: closures composing and restoring lane permissions in every
// end order, re-routing around closed edges, a spawn once per activation, traffic lights held and
// given back to their programme, the time-only rule for conditions, and the event log's lines.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sbsim/kernel/Simulation.h"
#include "sbsim/storyboard/EventLog.h"
#include "sbsim/storyboard/StoryCheck.h"
#include "sbsim/storyboard/StoryError.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/WorldStory.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/CarSetCondition.h"
#include "sbsim/storyboard/conditions/HoldCondition.h"
#include "sbsim/storyboard/conditions/LimitCondition.h"
#include "sbsim/storyboard/conditions/NotCondition.h"
#include "sbsim/storyboard/conditions/OrCondition.h"
#include "sbsim/storyboard/conditions/RisingCondition.h"
#include "sbsim/storyboard/conditions/SpeedCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/effects/CloseRoadEffect.h"
#include "sbsim/storyboard/effects/RemoveVehicleEffect.h"
#include "sbsim/storyboard/effects/SpawnEffect.h"
#include "sbsim/storyboard/effects/TrafficLightEffect.h"
#include "sbsim/storyboard/effects/TrafficLightPhaseEffect.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::storyboard {
namespace {

using kernel::SimTime;
using traffic::LanePermissions;

/// A network of named edges (lanes "<edge>_<i>"), vehicles with routes and traffic lights, that
/// records every command. Routes around a closed edge: the model's findRoute drops closed edges
/// from the route when a detour is declared for them.
class ModelNetwork : public traffic::NetworkController {
public:
    struct Car {
        std::vector<std::string> route;
        int index = -1;  // -1: waiting to depart
        std::string type = "car";
    };
    struct Light {
        std::string state;
        std::string program = "0";
        int phase = 0;
    };

    ModelNetwork() {
        for (const char* e : {"a", "b", "c", "d"}) edges[e] = 2;
        for (const auto& [edge, n] : edges) {
            for (int i = 0; i < n; ++i) lanePermissions[edge + "_" + std::to_string(i)] = {{"passenger", "truck"}, {}};
        }
        lanePermissions["b_1"] = {{"bus"}, {"passenger", "truck"}};  // a bus lane
        lights["J1"] = {"GGrr", "0", 2};
    }

    bool hasEdge(const std::string& edge) const override { return edges.contains(edge); }
    std::vector<std::string> lanes(const std::string& edge) const override {
        std::vector<std::string> out;
        for (int i = 0; i < edges.at(edge); ++i) out.push_back(edge + "_" + std::to_string(i));
        return out;
    }
    LanePermissions permissions(const std::string& lane) const override { return lanePermissions.at(lane); }
    void setPermissions(const std::string& lane, const LanePermissions& p) override {
        lanePermissions[lane] = p;
        log.push_back("permissions " + lane);
    }
    void closeLane(const std::string& lane) override {
        lanePermissions[lane] = {{}, {"all"}};
        log.push_back("close " + lane);
    }
    std::vector<std::string> knownVehicles() const override {
        std::vector<std::string> out;
        for (const auto& [id, car] : cars) out.push_back(id);
        return out;
    }
    std::vector<std::string> loadedVehicles() const override { return loaded; }
    std::vector<std::string> departedVehicles() const override { return departed; }
    bool routeValid(const std::string& v) const override { return !broken.contains(v); }
    bool routedBySumo(const std::string& v) const override { return trips.contains(v); }
    bool routeChecks() const override { return checks; }
    void setRouteChecks(bool on) override {
        if (on != checks) log.push_back(on ? "checks on" : "checks off");
        checks = on;
    }
    bool hasVehicle(const std::string& id) const override { return cars.contains(id); }
    bool hasDeparted(const std::string& id) const override { return cars.at(id).index >= 0; }
    std::vector<std::string> route(const std::string& v) const override { return cars.at(v).route; }
    int routeIndex(const std::string& v) const override { return cars.at(v).index; }
    std::string vehicleType(const std::string& v) const override { return cars.at(v).type; }
    bool closedEdge(const std::string& edge) const { return lanePermissions.at(edge + "_0").allowed.empty(); }
    std::vector<std::string> findRoute(const std::string& from, const std::string& to,
                                       const std::string&) const override {
        if (closedEdge(from) || closedEdge(to)) return {};
        std::vector<std::string> out{from};
        for (const std::string& e : std::vector<std::string>{"b", "c"}) {
            if (e != from && e != to && !closedEdge(e)) out.push_back(e);
        }
        if (to != from) out.push_back(to);
        return out;
    }
    void reroute(const std::string& v) override {
        Car& car = cars.at(v);
        const std::size_t from = static_cast<std::size_t>(std::max(car.index, 0));
        std::vector<std::string> way(car.route.begin(), car.route.begin() + static_cast<std::ptrdiff_t>(from));
        for (const std::string& e : findRoute(car.route[from], car.route.back(), car.type)) way.push_back(e);
        car.route = way;
        log.push_back("reroute " + v);
    }
    void removeVehicle(const std::string& v) override {
        cars.erase(v);
        log.push_back("remove " + v);
    }
    bool hasRoute(const std::string& id) const override { return routes.contains(id); }
    void addRoute(const std::string& id, const std::vector<std::string>& edges) override { routes[id] = edges; }
    void addVehicle(const traffic::VehicleSpawn& s) override {
        cars[s.id] = {routes.at(s.routeId), -1, s.typeId};
        log.push_back("add " + s.id + " " + s.routeId + " " + s.typeId + " " + s.departLane + " " + s.departPos + " " +
                      s.departSpeed);
    }
    bool hasTrafficLight(const std::string& tls) const override { return lights.contains(tls); }
    std::string signalState(const std::string& tls) const override { return lights.at(tls).state; }
    std::string program(const std::string& tls) const override { return lights.at(tls).program; }
    int phase(const std::string& tls) const override { return lights.at(tls).phase; }
    void setSignalState(const std::string& tls, const std::string& state) override {
        lights.at(tls).state = state;
        lights.at(tls).program = "online";
        log.push_back("state " + tls + " " + state);
    }
    void setProgram(const std::string& tls, const std::string& program) override {
        lights.at(tls).program = program;
        log.push_back("program " + tls + " " + program);
    }
    void setPhase(const std::string& tls, int phase) override {
        lights.at(tls).phase = phase;
        lights.at(tls).state = "rrGG";  // the model's phase 2
        log.push_back("phase " + tls + " " + std::to_string(phase));
    }

    std::map<std::string, int> edges;
    std::map<std::string, LanePermissions> lanePermissions;
    std::map<std::string, Car> cars;
    std::map<std::string, std::vector<std::string>> routes;
    std::map<std::string, Light> lights;
    std::vector<std::string> loaded;
    std::vector<std::string> departed;
    std::set<std::string> broken;  // vehicles whose route SUMO finds disconnected
    std::set<std::string> trips;   // vehicles SUMO routes itself
    bool checks = true;            // SUMO's route checks (on unless --ignore-route-errors)
    std::vector<std::string> log;
};

ConditionPtr window(double begin, double end) {
    return std::make_shared<TimeCondition>(SimTime::fromSeconds(begin), SimTime::fromSeconds(end));
}

StoryPtr world(ConditionPtr c, std::vector<WorldEffectPtr> effects, std::string name) {
    return std::make_shared<WorldStory>(std::move(c), std::move(effects), std::move(name));
}

WorldEffectPtr closure(std::vector<std::string> edges) { return std::make_shared<CloseRoadEffect>(std::move(edges)); }

class WorldStoryTest : public testing::Test {
protected:
    WorldStoryTest() : log(out), board(sim.emplaceModule<Storyboard>(registry, &log)) {
        auto model = std::make_unique<ModelNetwork>();
        network = model.get();
        board.setNetworkController(std::move(model));
    }

    void step(double t) {
        snapshot.assign({}, SimTime::fromSeconds(t));
        board.update(snapshot, {});
        network->loaded.clear();
        network->departed.clear();
    }
    void run(double from, double to) {
        for (double t = from; t <= to; t += 1) step(t);
    }
    void overlap(bool firstEndsFirst);

public:
    void runFrom(double from, double to) { run(from, to); }

protected:
    std::vector<std::string> lines() {
        std::vector<std::string> lines;
        std::istringstream in(out.str());
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        out.str("");
        return lines;
    }

    std::ostringstream out;
    EventLog log;
    traffic::VehicleRegistry registry;
    kernel::Simulation sim{7};
    Storyboard& board;
    ModelNetwork* network = nullptr;
    traffic::VehicleSnapshot snapshot;
};

TEST_F(WorldStoryTest, LogsActivationAndDeactivationWithVehicleNull) {
    board.registerStory(world(window(2, 3), {closure({"b"})}, "close"));
    run(1, 4);
    EXPECT_EQ(lines(), (std::vector<std::string>{
                           R"({"t":2,"type":"activate","story":"close","vehicle":null})",
                           R"({"t":4,"type":"deactivate","story":"close","vehicle":null,"reason":"condition"})",
                       }));
    EXPECT_EQ(board.stories()[0]->counters().activations(), 1u);
    EXPECT_DOUBLE_EQ(board.stories()[0]->counters().activeVehicleSeconds(), 2.0);
}

TEST_F(WorldStoryTest, ClosureRestoresThePermissionsRecordedAtApply) {
    const auto before = network->lanePermissions;
    board.registerStory(world(window(2, 3), {closure({"b"})}, "close"));
    step(2);
    EXPECT_TRUE(board.isActive(*board.stories()[0]));
    EXPECT_EQ(network->lanePermissions.at("b_0"), (LanePermissions{{}, {"all"}}));
    EXPECT_EQ(network->lanePermissions.at("b_1"), (LanePermissions{{}, {"all"}}));
    EXPECT_EQ(board.network().closedEdges(), (std::set<std::string>{"b"}));
    run(3, 4);
    EXPECT_EQ(network->lanePermissions, before);  // the bus lane is a bus lane again
    EXPECT_TRUE(board.network().closedEdges().empty());
}

/// Two overlapping closures of b (one also closing c), ending in either order: b opens only with
/// the last, and every lane gets exactly its own permissions back.
void WorldStoryTest::overlap(bool firstEndsFirst) {
    const auto before = network->lanePermissions;
    board.registerStory(world(window(2, firstEndsFirst ? 4 : 8), {closure({"b", "c"})}, "one"));
    board.registerStory(world(window(3, firstEndsFirst ? 8 : 4), {closure({"b"})}, "two"));
    run(2, 3);
    EXPECT_EQ(board.network().closedEdges(), (std::set<std::string>{"b", "c"}));
    const auto closes = std::count_if(network->log.begin(), network->log.end(),
                                      [](const std::string& l) { return l.starts_with("close b"); });
    EXPECT_EQ(closes, 2) << "each lane of b closed once";
    run(4, 5);  // one of them ended
    EXPECT_TRUE(board.network().closed("b"));
    EXPECT_EQ(board.network().closed("c"), !firstEndsFirst);
    EXPECT_EQ(network->lanePermissions.at("b_1"), (LanePermissions{{}, {"all"}}));
    run(6, 9);
    EXPECT_TRUE(board.network().closedEdges().empty());
    EXPECT_EQ(network->lanePermissions, before);
}

TEST_F(WorldStoryTest, OverlappingClosuresFirstEndingFirst) { overlap(true); }
TEST_F(WorldStoryTest, OverlappingClosuresSecondEndingFirst) { overlap(false); }

TEST_F(WorldStoryTest, ReroutesRunningAndWaitingVehiclesAroundAClosedEdge) {
    network->cars["on-a"] = {{"a", "b", "d"}, 0};
    network->cars["on-b"] = {{"b", "c", "d"}, 0};  // on the closed edge: drives off it
    network->cars["past"] = {{"a", "b", "d"}, 2};  // b behind it
    network->cars["waits"] = {{"a", "b", "d"}, -1};
    network->cars["ends-on-b"] = {{"a", "b"}, -1};
    step(1);
    board.registerStory(world(window(2, 5), {closure({"b"})}, "close"));
    step(2);
    EXPECT_EQ(network->cars.at("on-a").route, (std::vector<std::string>{"a", "c", "d"}));
    EXPECT_EQ(network->cars.at("on-b").route, (std::vector<std::string>{"b", "c", "d"}));
    EXPECT_EQ(network->cars.at("past").route, (std::vector<std::string>{"a", "b", "d"}));
    EXPECT_EQ(network->cars.at("waits").route, (std::vector<std::string>{"a", "c", "d"}));
    EXPECT_FALSE(network->cars.contains("ends-on-b")) << "it would stop SUMO when inserted";
    // Loaded while closed: steered at once.
    network->cars["later"] = {{"d", "b", "a"}, -1};
    network->loaded = {"later"};
    step(3);
    EXPECT_EQ(network->cars.at("later").route, (std::vector<std::string>{"d", "c", "a"}));
    // Off the closed edge, the vehicle that was on it is looked at again.
    network->cars.at("on-b") = {{"b", "c", "b", "d"}, 1};
    step(4);
    EXPECT_EQ(network->cars.at("on-b").route, (std::vector<std::string>{"b", "c", "d"}));
    // After the closure nothing is re-routed.
    run(5, 6);
    network->cars["free"] = {{"a", "b", "d"}, -1};
    network->loaded = {"free"};
    step(7);
    EXPECT_EQ(network->cars.at("free").route, (std::vector<std::string>{"a", "b", "d"}));
}

/// SUMO makes a flow's vehicle in the step it inserts it: with its route checks on, one whose trip
/// the closure cut would stop the run inside that step, so they are off while any edge is closed.
void routeChecksWhileClosed(WorldStoryTest& t, ModelNetwork& network, Storyboard& board, bool before) {
    network.checks = before;
    board.registerStory(world(window(2, 5), {closure({"b"})}, "one"));
    board.registerStory(world(window(3, 8), {closure({"b", "c"})}, "two"));
    t.runFrom(1, 1);
    EXPECT_EQ(network.checks, before);
    t.runFrom(2, 8);
    EXPECT_FALSE(network.checks) << "off while either closure is active";
    EXPECT_EQ(std::count(network.log.begin(), network.log.end(), "checks off"), before ? 1 : 0) << "turned off once";
    t.runFrom(9, 9);
    EXPECT_EQ(network.checks, before) << "back as they were after the last";
}

TEST_F(WorldStoryTest, RouteChecksAreOffWhileAnEdgeIsClosed) { routeChecksWhileClosed(*this, *network, board, true); }
TEST_F(WorldStoryTest, RouteChecksTheUserTurnedOffStayOff) { routeChecksWhileClosed(*this, *network, board, false); }

TEST_F(WorldStoryTest, AVehicleSumoInsertedInTheStepThatMadeItIsRemovedIfTheClosureCutItsTrip) {
    board.registerStory(world(window(2, 5), {closure({"b"})}, "close"));
    run(1, 2);
    // A flow's vehicles, made and inserted by SUMO in step 3: on their first edge, not moved yet.
    network->cars["to-b"] = {{"a", "b"}, 0};             // a trip SUMO could not route: the route it had
    network->cars["through-b"] = {{"a", "b", "d"}, 0};   // a fixed route with a way around
    network->loaded = {"to-b", "through-b", "dropped"};  // SUMO dropped the last one: its first edge was b
    network->departed = {"to-b", "through-b"};
    testing::internal::CaptureStderr();
    step(3);
    const std::string warnings = testing::internal::GetCapturedStderr();
    EXPECT_NE(warnings.find("vehicle 'to-b' removed in the step SUMO made and inserted it"), std::string::npos);
    EXPECT_NE(warnings.find("vehicle 'dropped' removed before it departed: SUMO dropped it"), std::string::npos);
    EXPECT_FALSE(network->cars.contains("to-b"));
    EXPECT_EQ(network->cars.at("through-b").route, (std::vector<std::string>{"a", "c", "d"}));
    // One whose route is broken for another reason ends the run, as SUMO's check would have.
    network->cars["broken"] = {{"a", "d"}, 0};
    network->broken = {"broken"};
    network->departed = {"broken"};
    EXPECT_THROW(step(4), traffic::SumoError);
}

TEST_F(WorldStoryTest, ATripSumoCouldNotRouteOnlyBecauseOfTheClosureIsRemoved) {
    board.registerStory(world(window(2, 5), {closure({"b"})}, "close"));
    run(1, 2);
    // SUMO found no way from a to d for these (all crossed b), so each keeps the route it had.
    network->cars["trip"] = {{"a", "d"}, 0};
    network->cars["fixed"] = {{"a", "d"}, 0};
    network->broken = {"trip", "fixed"};
    network->trips = {"trip"};
    network->departed = {"trip"};
    step(3);
    EXPECT_FALSE(network->cars.contains("trip"));
    EXPECT_EQ(network->lanePermissions.at("b_0"), (LanePermissions{{}, {"all"}})) << "closed again after the question";
    network->departed = {"fixed"};  // a fixed route SUMO would have refused anyway
    EXPECT_THROW(step(4), traffic::SumoError);
}

TEST_F(WorldStoryTest, ASpawnDuringAClosureIsCheckedAsSumoChecksWithNoEdgeClosed) {
    board.registerStory(world(window(2, 5), {closure({"b"})}, "close"));
    board.registerStory(
        world(window(3, 3), {std::make_shared<SpawnEffect>(SpawnEffect::Spec{"v", {"a", "c"}})}, "spawn"));
    run(1, 3);
    EXPECT_TRUE(network->cars.contains("v"));
    EXPECT_EQ(network->log.end()[-3], "checks on") << "SUMO checks the new vehicle's route";
    EXPECT_EQ(network->log.end()[-1], "checks off") << "and the closure has them off again";
}

TEST_F(WorldStoryTest, RemoveVehicleTakesTheVehicleOutOnceAndTheVehiclePassLeavesItAlone) {
    network->cars["v"] = {{"a", "b"}, 0};
    network->cars["w"] = {{"a", "b"}, -1};
    board.registerStory(world(window(2, 5),
                              {std::make_shared<RemoveVehicleEffect>("v"), std::make_shared<RemoveVehicleEffect>("w"),
                               std::make_shared<RemoveVehicleEffect>("gone")},
                              "delete"));
    step(1);
    EXPECT_TRUE(network->cars.contains("v"));
    step(2);
    EXPECT_FALSE(network->cars.contains("v"));
    EXPECT_FALSE(network->cars.contains("w")) << "one waiting to depart too";
    EXPECT_EQ(board.network().removedAfterInsertion(), (std::vector<std::string>{"v"})) << "w never ran";
    EXPECT_EQ(std::count(network->log.begin(), network->log.end(), "remove v"), 1);
    EXPECT_EQ(RemoveVehicleEffect("v").describe(), "RemoveVehicleEffect('v')");
    EXPECT_THROW(RemoveVehicleEffect(""), std::invalid_argument);
}

TEST_F(WorldStoryTest, UnknownEdgeIsAStoryErrorNamingStoryEffectAndTime) {
    board.registerStory(world(window(2, 5), {closure({"b", "nope"})}, "close"));
    step(1);
    try {
        step(2);
        FAIL() << "no error";
    } catch (const StoryError& e) {
        EXPECT_STREQ(e.what(), "story 'close': CloseRoadEffect at t=2 s: no edge 'nope' in the network");
    }
    EXPECT_EQ(network->lanePermissions.at("b_0").allowed, (std::vector<std::string>{"passenger", "truck"}))
        << "nothing closed";
}

TEST_F(WorldStoryTest, SpawnsOnceAtActivationAndRemovingDoesNothing) {
    SpawnEffect::Spec spec;
    spec.id = "truck";
    spec.route = {"a", "b"};
    spec.type = "lorry";
    spec.lane = "0";
    spec.position = "300";
    board.registerStory(world(window(2, 3), {std::make_shared<SpawnEffect>(spec)}, "spawn"));
    run(1, 5);
    EXPECT_EQ(network->log, (std::vector<std::string>{"add truck sbsim:spawn:truck lorry 0 300 0"}));
    EXPECT_EQ(network->cars.at("truck").route, (std::vector<std::string>{"a", "b"}));
}

TEST_F(WorldStoryTest, SpawnFromToFindsTheRouteAndTakesSumoDefaults) {
    SpawnEffect::Spec spec;
    spec.id = "v";
    spec.from = "a";
    spec.to = "d";
    network->routes["sbsim:spawn:v"] = {"x"};  // taken: a route id of its own
    board.registerStory(world(window(2, 3), {std::make_shared<SpawnEffect>(spec)}, "spawn"));
    run(1, 2);
    EXPECT_EQ(network->log, (std::vector<std::string>{"add v sbsim:spawn:v#1 DEFAULT_VEHTYPE first base 0"}));
    EXPECT_EQ(network->cars.at("v").route, (std::vector<std::string>{"a", "b", "c", "d"}));
}

TEST_F(WorldStoryTest, SpawnOfAnExistingVehicleIsAStoryError) {
    network->cars["x"] = {{"a"}, 0};
    SpawnEffect::Spec dup;
    dup.id = "x";
    dup.route = {"a"};
    board.registerStory(world(window(2, 3), {std::make_shared<SpawnEffect>(dup)}, "dup"));
    EXPECT_THROW(
        {
            try {
                run(1, 2);
            } catch (const StoryError& e) {
                EXPECT_STREQ(e.what(), "story 'dup': SpawnEffect at t=2 s: vehicle 'x' exists already");
                throw;
            }
        },
        StoryError);
    SpawnEffect::Spec noRoute;
    noRoute.id = "y";
    EXPECT_THROW(SpawnEffect{noRoute}, std::invalid_argument);
}

TEST_F(WorldStoryTest, SpawnOnAnUnknownEdgeIsAStoryError) {
    SpawnEffect::Spec bad;
    bad.id = "y";
    bad.from = "a";
    bad.to = "zz";
    board.registerStory(world(window(0, 3), {std::make_shared<SpawnEffect>(bad)}, "bad"));
    try {
        step(1);
        FAIL() << "no error";
    } catch (const StoryError& e) {
        EXPECT_STREQ(e.what(), "story 'bad': SpawnEffect at t=1 s: no edge 'zz' in the network");
    }
}

TEST_F(WorldStoryTest, TrafficLightIsHeldThenItsProgrammeResumesAtTheRecordedPhase) {
    board.registerStory(world(window(2, 4), {std::make_shared<TrafficLightEffect>("J1", "rrrr")}, "red"));
    board.registerStory(world(window(3, 5), {std::make_shared<TrafficLightEffect>("J1", "GGGG")}, "green"));
    step(2);
    EXPECT_EQ(network->lights.at("J1").state, "rrrr");
    step(3);
    EXPECT_EQ(network->lights.at("J1").state, "GGGG");  // the latest rules
    step(5);                                            // red ended: green still holds
    EXPECT_EQ(network->lights.at("J1").state, "GGGG");
    EXPECT_EQ(board.network().heldState("J1"), "GGGG");
    step(6);
    EXPECT_EQ(network->log, (std::vector<std::string>{"state J1 rrrr", "state J1 GGGG", "program J1 0", "phase J1 2"}));
    EXPECT_FALSE(board.network().heldState("J1"));
}

TEST_F(WorldStoryTest, TrafficLightErrors) {
    EXPECT_THROW(TrafficLightEffect("J1", "rxr"), std::invalid_argument);
    EXPECT_THROW(TrafficLightEffect("", "r"), std::invalid_argument);
    board.registerStory(world(window(2, 4), {std::make_shared<TrafficLightEffect>("J1", "rr")}, "short"));
    try {
        step(2);
        FAIL() << "no error";
    } catch (const StoryError& e) {
        EXPECT_STREQ(e.what(),
                     "story 'short': TrafficLightEffect at t=2 s: the state 'rr' has 2 signals, traffic light 'J1' "
                     "controls 4");
    }
    NetworkStack stack(*network);
    EXPECT_THROW(stack.pushSignalState(1, "nope", "r"), std::invalid_argument);
}

TEST_F(WorldStoryTest, TrafficLightLinksTakeTheLetterAndTheOthersKeepTheirs) {
    board.registerStory(
        world(window(2, 3), {std::make_shared<TrafficLightEffect>("J1", "r", std::vector<int>{0, 1})}, "red links"));
    step(2);
    EXPECT_EQ(network->lights.at("J1").state, "rrrr") << "GGrr with links 0 and 1 red";
    step(4);
    EXPECT_EQ(network->log, (std::vector<std::string>{"state J1 rrrr", "program J1 0", "phase J1 2"}));
    EXPECT_EQ(TrafficLightEffect("J1", "r", {0, 1}).describe(), "TrafficLightEffect('J1', 'r', links 0,1)");
    EXPECT_THROW(TrafficLightEffect("J1", "rr", {0}), std::invalid_argument);
    EXPECT_THROW(TrafficLightEffect("J1", "r", {-1}), std::invalid_argument);
    board.registerStory(
        world(window(5, 6), {std::make_shared<TrafficLightEffect>("J1", "r", std::vector<int>{4})}, "beyond"));
    try {
        step(5);
        FAIL() << "no error";
    } catch (const StoryError& e) {
        EXPECT_STREQ(e.what(),
                     "story 'beyond': TrafficLightEffect at t=5 s: traffic light 'J1' has no link 4 (it controls 4)");
    }
}

TEST_F(WorldStoryTest, AKeptTrafficLightStateOutlastsItsStoryUntilALaterHold) {
    board.registerStory(
        world(window(2, 2), {std::make_shared<TrafficLightEffect>("J1", "rrrr", std::vector<int>{}, true)}, "kept"));
    board.registerStory(world(window(5, 6), {std::make_shared<TrafficLightEffect>("J1", "GGGG")}, "green"));
    run(2, 4);
    EXPECT_FALSE(board.isActive(*board.stories()[0]));
    EXPECT_EQ(network->lights.at("J1").state, "rrrr") << "the story ended, the light stays red";
    EXPECT_EQ(board.network().heldState("J1"), "rrrr");
    step(5);
    EXPECT_EQ(network->lights.at("J1").state, "GGGG") << "a later hold rules";
    step(7);
    EXPECT_EQ(network->lights.at("J1").state, "rrrr") << "and when it ends, the kept state is back";
    EXPECT_EQ(network->log, (std::vector<std::string>{"state J1 rrrr", "state J1 GGGG", "state J1 rrrr"}));
    EXPECT_EQ(TrafficLightEffect("J1", "rrrr", {}, true).describe(), "TrafficLightEffect('J1', 'rrrr', kept)");
}

TEST_F(WorldStoryTest, APhaseSwitchEndsTheHoldsOfTheLightAndItsProgrammeGoesOn) {
    board.registerStory(
        world(window(2, 2), {std::make_shared<TrafficLightEffect>("J1", "rrrr", std::vector<int>{}, true)}, "kept"));
    board.registerStory(world(window(4, 5), {std::make_shared<TrafficLightPhaseEffect>("J1", 2)}, "phase"));
    run(2, 7);
    EXPECT_EQ(network->log, (std::vector<std::string>{"state J1 rrrr", "program J1 0", "phase J1 2"}))
        << "the kept red ends, the programme is back, at phase 2; the story's end changes nothing";
    EXPECT_FALSE(board.network().heldState("J1"));
    EXPECT_EQ(network->lights.at("J1").state, "rrGG");
    EXPECT_EQ(TrafficLightPhaseEffect("J1", 2).describe(), "TrafficLightPhaseEffect('J1', phase 2)");
    EXPECT_THROW(TrafficLightPhaseEffect("J1", -1), std::invalid_argument);
    EXPECT_THROW(TrafficLightPhaseEffect("", 0), std::invalid_argument);
    NetworkStack stack(*network);
    EXPECT_THROW(stack.switchPhase("nope", 0), std::invalid_argument);
}

TEST_F(WorldStoryTest, AcceptsTimeOnlyConditionsAndRefusesOthersNamingThem) {
    const auto t = window(1, 2);
    EXPECT_NO_THROW(world(std::make_shared<OrCondition>(std::make_shared<NotCondition>(t),
                                                        std::make_shared<AndCondition>(
                                                            std::make_shared<HoldCondition>(t, SimTime::fromSeconds(1)),
                                                            std::make_shared<RisingCondition>(t))),
                          {}, "ok"));
    try {
        world(std::make_shared<AndCondition>(t, std::make_shared<SpeedConditionGreater>(3.0)), {}, "bad");
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("got SpeedConditionGreater"), std::string::npos) << e.what();
    }
    EXPECT_THROW(world(std::make_shared<CarSetCondition>(std::set<std::string>{"a"}), {}, "bad"),
                 std::invalid_argument);
}

/// A condition the storyboard does not know that looks at the time only (every other minute).
class OddMinutes : public Condition {
public:
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex) override {
        return static_cast<long>(ctx.now().seconds() / 60) % 2 == 1;
    }
    bool timeOnly() const override { return true; }
};

TEST_F(WorldStoryTest, AConditionThatSaysItIsTimeOnlyIsAccepted) {
    EXPECT_NO_THROW(world(std::make_shared<NotCondition>(std::make_shared<OddMinutes>()), {}, "odd"));
    // The first leaf that looks at more is named, however deep.
    try {
        world(std::make_shared<OrCondition>(std::make_shared<OddMinutes>(),
                                            std::make_shared<NotCondition>(std::make_shared<HoldCondition>(
                                                std::make_shared<LimitCondition>(1), SimTime::fromSeconds(1)))),
              {}, "bad");
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("got LimitCondition"), std::string::npos) << e.what();
    }
}

TEST_F(WorldStoryTest, HoldAndRisingKeepTheWorldsStateOnce) {
    board.registerStory(world(std::make_shared<HoldCondition>(window(2, 10), SimTime::fromSeconds(2)), {}, "held"));
    board.registerStory(world(std::make_shared<RisingCondition>(window(2, 10)), {}, "rise"));
    run(1, 12);
    EXPECT_EQ(lines(), (std::vector<std::string>{
                           R"({"t":2,"type":"activate","story":"rise","vehicle":null})",
                           R"({"t":3,"type":"deactivate","story":"rise","vehicle":null,"reason":"condition"})",
                           R"({"t":4,"type":"activate","story":"held","vehicle":null})",
                           R"({"t":11,"type":"deactivate","story":"held","vehicle":null,"reason":"condition"})",
                       }));
}

TEST_F(WorldStoryTest, CheckListsWorldEffects) {
    SpawnEffect::Spec spec;
    spec.id = "truck";
    spec.route = {"a", "b"};
    const auto story = world(
        window(2, 3),
        {closure({"b", "c"}), std::make_shared<SpawnEffect>(spec), std::make_shared<TrafficLightEffect>("J1", "rrGG")},
        "w");
    std::vector<std::string> texts;
    for (const auto& node : describeStory(*story)) texts.push_back(node.text);
    EXPECT_EQ(texts, (std::vector<std::string>{"world story: acts on the network", "TimeCondition(2 s, 3 s)",
                                               "→ CloseRoadEffect(b, c)", "→ SpawnEffect('truck', route a b)",
                                               "→ TrafficLightEffect('J1', 'rrGG')"}));
}

}  // namespace
}  // namespace sbsim::storyboard
