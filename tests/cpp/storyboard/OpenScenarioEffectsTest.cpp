// The effects OpenSCENARIO's event actions build, on model vehicles that record their SUMO
// commands: TeleportEffect (on the route, off it, relative to another vehicle) and RouteEffect
// kept (a RoutingAction: routed once, left so).

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/effects/RouteEffect.h"
#include "sbsim/storyboard/effects/TeleportEffect.h"
#include "sbsim/traffic/EffectStack.h"

namespace sbsim::storyboard {
namespace {

using Log = std::vector<std::string>;

/// A vehicle on `road` (lane `lane`, `position` m) with a route; its commands go to `log`.
class ModelVehicle : public traffic::VehicleController {
public:
    ModelVehicle(const std::string& id, Log& log) : VehicleController(id), log_(log) {}
    std::string roadId() const override { return road; }
    int laneIndex() const override { return lane; }
    double lanePosition() const override { return position; }
    std::vector<std::string> route() const override { return edges; }
    void moveTo(const std::string& laneId, double pos) override {
        log_.push_back("moveTo " + laneId + " " + std::to_string(static_cast<int>(pos)));
    }
    void changeTarget(const std::string& edge) override {
        if (edge == "nowhere") throw traffic::CommandRefused("no connection");
        log_.push_back("changeTarget " + edge);
    }
    void setRoute(const std::vector<std::string>& route) override {
        std::string s = "setRoute";
        for (const auto& e : route) s += " " + e;
        log_.push_back(s);
    }
    void setVia(const std::vector<std::string>& via) override {
        std::string s = "setVia";
        for (const auto& e : via) s += " " + e;
        log_.push_back(s);
    }

    std::string road = "a";
    int lane = 0;
    double position = 0;
    std::vector<std::string> edges{"a", "b", "c"};

private:
    Log& log_;
};

/// One activation's scope: the ego and the other vehicles by id.
class Scope : public EffectScope {
public:
    explicit Scope(Log& log) : ego(std::make_shared<ModelVehicle>("ego", log)), stack_(*ego) {}
    const Story& story() const override { return story_; }
    const std::string& vehicleId() const override { return ego->id(); }
    traffic::VehicleController& vehicle() override { return *ego; }
    VehicleHandle handle() override { return VehicleHandle(ego->id(), ego); }
    traffic::EffectStack& stack() override { return stack_; }
    traffic::EffectStack::Token token() const override { return 1; }
    const std::vector<std::string>& others() const override { return others_; }
    void emitSignal(const std::string& /*cause*/, bool /*onExit*/) override {}
    std::shared_ptr<traffic::VehicleController> controllerOf(const std::string& id) override { return vehicles.at(id); }

    std::shared_ptr<ModelVehicle> ego;
    std::map<std::string, std::shared_ptr<ModelVehicle>> vehicles;

private:
    Story story_{std::make_shared<TimeCondition>(kernel::SimTime::zero()), {}, "S/A/E"};
    traffic::EffectStack stack_;
    std::vector<std::string> others_;
};

TEST(TeleportEffect, OnItsRouteTheVehicleIsMovedAndKeepsItsRoute) {
    Log log;
    Scope scope(log);
    TeleportEffect jump({"b", 1, 20.0, std::nullopt}, {"b", "z"});
    jump.apply(scope);
    EXPECT_EQ(log, (Log{"moveTo b_1 20"}));
    EXPECT_TRUE(jump.complete());
    jump.remove(scope);
    EXPECT_EQ(log.size(), 1u) << "nothing to undo";
    EXPECT_EQ(jump.describe(), "TeleportEffect(b_1 at 20 m)");
}

TEST(TeleportEffect, OffItsRouteItIsRoutedThereFirstThenDrivesOnward) {
    Log log;
    Scope scope(log);
    TeleportEffect(TeleportEffect::Target{"x", 0, 5.0, std::nullopt}, {"x", "y"}).apply(scope);
    EXPECT_EQ(log, (Log{"changeTarget x", "moveTo x_0 5", "setRoute x y"}));
    log.clear();
    TeleportEffect(TeleportEffect::Target{"x", 0, 5.0, std::nullopt}).apply(scope);
    EXPECT_EQ(log, (Log{"changeTarget x", "moveTo x_0 5", "changeTarget c"})) << "without onward: its destination";
    TeleportEffect unreachable({"nowhere", 0, 5.0, std::nullopt});
    EXPECT_THROW(unreachable.apply(scope), traffic::CommandRefused) << "the story's error: exit code 2";
}

TEST(TeleportEffect, RelativeToAVehicleWhereItIsAtActivation) {
    Log log;
    Scope scope(log);
    auto lead = std::make_shared<ModelVehicle>("lead", log);
    lead->road = "b";
    lead->lane = 0;
    lead->position = 100;
    scope.vehicles["lead"] = lead;
    TeleportEffect behind({"", 1, -30.0, "lead"});
    behind.apply(scope);
    EXPECT_EQ(log, (Log{"moveTo b_1 70"})) << "one lane left of lead's, 30 m behind it";
    EXPECT_EQ(behind.describe(), "TeleportEffect(lead's lane +1, -30 m)");
    EXPECT_THROW(TeleportEffect({"", 0, 0.0, std::nullopt}), std::invalid_argument);
    EXPECT_THROW(TeleportEffect({"b", -1, 0.0, std::nullopt}), std::invalid_argument);
    EXPECT_THROW(TeleportEffect({"b", 0, 0.0, std::nullopt}, {"c"}), std::invalid_argument)
        << "the onward route starts on the target edge";
}

TEST(RouteEffect, KeptItRoutesOnceThroughViaAndLeavesTheRouteSo) {
    Log log;
    Scope scope(log);
    RouteEffect route("t", {"a", "m"}, true);
    route.apply(scope);
    EXPECT_EQ(log, (Log{"setVia m", "changeTarget t"})) << "the edge it is on needs no passing";
    EXPECT_TRUE(route.complete());
    route.remove(scope);
    EXPECT_EQ(log.size(), 2u) << "kept: nothing restored";
    log.clear();
    RouteEffect(std::nullopt, {"m"}, true).apply(scope);
    EXPECT_EQ(log, (Log{"setVia m", "changeTarget c"})) << "no target: its own destination";
    EXPECT_EQ(RouteEffect("t", {"m"}, true).describe(), "RouteEffect(to t, via m, kept)");
    EXPECT_EQ(RouteEffect("t", {}).describe(), "RouteEffect(to t)");
    EXPECT_THROW(RouteEffect("t", {"m"}), std::invalid_argument) << "not kept: one of them";
    EXPECT_THROW(RouteEffect(std::nullopt, {}, true), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::storyboard
