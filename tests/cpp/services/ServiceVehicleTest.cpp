// A service's speed cap and a story's on one vehicle: both go on the vehicle's one effect stack
// (traffic::VehicleRegistry), so they compose like two stories' caps in every order.

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "sbsim/kernel/Simulation.h"
#include "sbsim/services/ServiceVehicle.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/effects/SpeedEffect.h"
#include "sbsim/traffic/VehicleRegistry.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::services {
namespace {

constexpr double kOwnMaxSpeed = 33.0;

/// A vehicle with a max speed and nothing else.
class CapModel : public traffic::VehicleController {
public:
    explicit CapModel(const std::string& id) : VehicleController(id) {}
    double maxSpeed() const override { return maxSpeed_; }
    void setMaxSpeed(double mps) override { maxSpeed_ = mps; }
    double maxSpeed_ = kOwnMaxSpeed;
};

double maxSpeedOf(const traffic::VehicleRegistry::Vehicle& v) { return v.controller->maxSpeed(); }

struct Order {
    bool serviceFirst;  // activation
    bool serviceEndsFirst;
};

const auto kEveryOrder =
    testing::Values(Order{true, true}, Order{true, false}, Order{false, true}, Order{false, false});

std::string orderName(const testing::TestParamInfo<Order>& info) {
    return std::string(info.param.serviceFirst ? "ServiceFirst" : "StoryFirst") +
           (info.param.serviceEndsFirst ? "ServiceEndsFirst" : "StoryEndsFirst");
}

class ServiceAndStoryCaps : public testing::TestWithParam<Order> {};

TEST_P(ServiceAndStoryCaps, ComposeLikeTwoStories) {
    const Order order = GetParam();
    traffic::VehicleRegistry registry;
    registry.setControllerFactory([](const std::string& id) { return std::make_unique<CapModel>(id); });
    const auto vehicle = registry.of("a");
    ServiceVehicle service(vehicle, registry);
    const traffic::EffectStack::Token story = registry.newToken();
    const auto storyCap = [&] { vehicle->stack.pushSpeedCap(story, 10.0); };
    if (order.serviceFirst) {
        service.setMaxSpeed(20.0);
        storyCap();
        EXPECT_EQ(maxSpeedOf(*vehicle), 10.0);
    } else {
        storyCap();
        service.setMaxSpeed(20.0);
        EXPECT_EQ(maxSpeedOf(*vehicle), 20.0);
    }
    if (order.serviceEndsFirst) {
        service.endMaxSpeed();
        EXPECT_EQ(maxSpeedOf(*vehicle), 10.0) << "the story's cap rules again";
        vehicle->stack.remove(story);
    } else {
        vehicle->stack.remove(story);
        EXPECT_EQ(maxSpeedOf(*vehicle), 20.0) << "the story ending must not undo the service's cap";
        service.endMaxSpeed();
    }
    EXPECT_EQ(maxSpeedOf(*vehicle), kOwnMaxSpeed);
    EXPECT_TRUE(vehicle->stack.empty());
}

INSTANTIATE_TEST_SUITE_P(EveryOrder, ServiceAndStoryCaps, kEveryOrder, orderName);

TEST(ServiceVehicle, ASecondCapReplacesTheServicesFirst) {
    traffic::VehicleRegistry registry;
    registry.setControllerFactory([](const std::string& id) { return std::make_unique<CapModel>(id); });
    const auto vehicle = registry.of("a");
    ServiceVehicle service(vehicle, registry);
    service.setMaxSpeed(20.0);
    service.setMaxSpeed(15.0);
    EXPECT_EQ(maxSpeedOf(*vehicle), 15.0);
    service.endMaxSpeed();
    EXPECT_EQ(maxSpeedOf(*vehicle), kOwnMaxSpeed);
    EXPECT_TRUE(vehicle->stack.empty());
}

TEST(ServiceVehicle, TheBoardAndAServiceShareTheVehiclesStack) {
    // A SpeedEffect story ending while a service's cap is set leaves the service's cap in force.
    traffic::VehicleRegistry registry;
    kernel::Simulation sim;
    registry.setControllerFactory([](const std::string& id) { return std::make_unique<CapModel>(id); });
    auto& board = sim.emplaceModule<storyboard::Storyboard>(registry);
    board.registerStory(std::make_shared<storyboard::Story>(
        std::make_shared<storyboard::TimeCondition>(kernel::SimTime::fromSeconds(1), kernel::SimTime::fromSeconds(2)),
        std::vector<storyboard::EffectPtr>{std::make_shared<storyboard::SpeedEffect>(10.0)}, "slow"));
    traffic::VehicleSnapshot snapshot;
    traffic::VehicleSnapshot::Vehicle car;
    car.id = "a";
    const auto step = [&](double t) {
        snapshot.assign({car}, kernel::SimTime::fromSeconds(t));
        board.update(snapshot, {});
    };
    step(1);
    const auto vehicle = registry.of("a");
    EXPECT_EQ(maxSpeedOf(*vehicle), 10.0);
    ServiceVehicle service(vehicle, registry);
    service.setMaxSpeed(20.0);
    step(2);
    step(3);  // the story ended
    EXPECT_EQ(maxSpeedOf(*vehicle), 20.0);
    service.endMaxSpeed();
    EXPECT_EQ(maxSpeedOf(*vehicle), kOwnMaxSpeed);
}

/// A vehicle with a destination and via edges, routed by changeTarget as SUMO would.
class RouteModel : public traffic::VehicleController {
public:
    explicit RouteModel(const std::string& id) : VehicleController(id) {}
    std::vector<std::string> route() const override { return {"here", destination_}; }
    std::vector<std::string> via() const override { return via_; }
    void setVia(const std::vector<std::string>& edges) override { via_ = edges; }
    void changeTarget(const std::string& edge) override { destination_ = edge; }
    std::string destination_ = "home";
    std::vector<std::string> via_;
};

const RouteModel& routeOf(const traffic::VehicleRegistry::Vehicle& v) {
    return static_cast<const RouteModel&>(*v.controller);
}

class ServiceAndStoryRoutes : public testing::TestWithParam<Order> {};

TEST_P(ServiceAndStoryRoutes, ComposeLikeTwoStories) {
    const Order order = GetParam();
    traffic::VehicleRegistry registry;
    registry.setControllerFactory([](const std::string& id) { return std::make_unique<RouteModel>(id); });
    const auto vehicle = registry.of("a");
    ServiceVehicle service(vehicle, registry);
    const traffic::EffectStack::Token story = registry.newToken();
    const auto storyRoute = [&] { vehicle->stack.pushRoute(story, {"bypass", {}}); };
    const auto serviceRoute = [&] {
        service.setVia({"bridge"});
        service.changeTarget("depot");  // keeps the via edge it set
    };
    if (order.serviceFirst) {
        serviceRoute();
        storyRoute();
        EXPECT_EQ(routeOf(*vehicle).destination_, "bypass");
        EXPECT_TRUE(routeOf(*vehicle).via_.empty());
    } else {
        storyRoute();
        serviceRoute();
        EXPECT_EQ(routeOf(*vehicle).destination_, "depot");
        EXPECT_EQ(routeOf(*vehicle).via_, std::vector<std::string>{"bridge"});
    }
    if (order.serviceEndsFirst) {
        service.endRoute();
        EXPECT_EQ(routeOf(*vehicle).destination_, "bypass") << "the story's route rules again";
        vehicle->stack.remove(story);
    } else {
        vehicle->stack.remove(story);
        EXPECT_EQ(routeOf(*vehicle).destination_, "depot") << "the story ending must not undo the service's route";
        EXPECT_EQ(routeOf(*vehicle).via_, std::vector<std::string>{"bridge"});
        service.endRoute();
    }
    EXPECT_EQ(routeOf(*vehicle).destination_, "home");
    EXPECT_TRUE(routeOf(*vehicle).via_.empty());
    EXPECT_TRUE(vehicle->stack.empty());
}

INSTANTIATE_TEST_SUITE_P(EveryOrder, ServiceAndStoryRoutes, kEveryOrder, orderName);

}  // namespace
}  // namespace sbsim::services
