// Conditions that read only the step's snapshot: distance to a point or a vehicle, standstill,
// acceleration, road, lane and type.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>

#include "StoryboardTestSupport.h"
#include "sbsim/storyboard/conditions/AccelerationCondition.h"
#include "sbsim/storyboard/conditions/DistanceCondition.h"
#include "sbsim/storyboard/conditions/LaneCondition.h"
#include "sbsim/storyboard/conditions/RoadCondition.h"
#include "sbsim/storyboard/conditions/StandstillCondition.h"
#include "sbsim/storyboard/conditions/TypeCondition.h"

namespace sbsim::storyboard::test {
namespace {

Vehicle on(std::string id, std::string lane, std::string type = "car", double acceleration = 0) {
    Vehicle v = car(std::move(id), 0, 0);
    v.road = lane.substr(0, lane.rfind('_'));
    v.lane = std::move(lane);
    v.type = std::move(type);
    v.acceleration = acceleration;
    return v;
}

TEST(DistanceCondition, ToAPointIsInclusive) {
    DistanceCondition c(Eigen::Vector2d(100, 0), 10);
    Scene scene({car("a", 90, 0), car("b", 89.9, 0), car("c", 106, 8), car("d", 107, 8)});
    EXPECT_TRUE(scene.test(c, "a"));
    EXPECT_FALSE(scene.test(c, "b"));
    EXPECT_TRUE(scene.test(c, "c"));  // 6-8-10
    EXPECT_FALSE(scene.test(c, "d"));
    EXPECT_FALSE(scene.test(c, "a").isSet());
}

TEST(DistanceCondition, ToAVehicleYieldsIt) {
    DistanceCondition c(std::string("target"), 10);
    Scene scene({car("a", 0, 0), car("b", 30, 0), car("target", 5, 5)});
    const ConditionResult r = scene.test(c, "a");
    EXPECT_TRUE(r);
    EXPECT_EQ(scene.others(r), (Ids{"target"}));
    EXPECT_FALSE(scene.test(c, "b"));
    EXPECT_TRUE(scene.test(c, "b").isSet());
    EXPECT_FALSE(scene.test(c, "target")) << "a set names other vehicles";
    // Without the target running, nobody is near it; the next step finds it again.
    scene.set({car("a", 0, 0)}, SimTime::fromSeconds(1));
    EXPECT_FALSE(scene.test(c, "a"));
    scene.set({car("a", 0, 0), car("target", 0, 10)}, SimTime::fromSeconds(2));
    EXPECT_TRUE(scene.test(c, "a"));
    // And without prepare() for the step it looks the target up itself.
    scene.set({car("a", 0, 0), car("target", 0, 11)}, SimTime::fromSeconds(3));
    EXPECT_FALSE(c.test(scene.ctx(), scene.index("a")));
}

TEST(DistanceCondition, RejectsBadArguments) {
    EXPECT_THROW(DistanceCondition(Eigen::Vector2d(0, 0), -1), std::invalid_argument);
    EXPECT_THROW(DistanceCondition(Eigen::Vector2d(0, std::nan("")), 1), std::invalid_argument);
    EXPECT_THROW(DistanceCondition(std::string(), 1), std::invalid_argument);
    EXPECT_TRUE(DistanceCondition(std::string("x"), 1).pure());
}

TEST(StandstillCondition, CountsContinuousStandingAtEveryStepWhetherTestedOrNot) {
    StandstillCondition c(SimTime::fromSeconds(2));
    Scene scene({car("a", 0, 0, 0.05), car("b", 0, 0, 0)}, SimTime::fromSeconds(1));
    const auto at = [&](int t, double va, double vb) {
        scene.set({car("a", 0, 0, va), car("b", 0, 0, vb)}, SimTime::fromSeconds(t));
        c.prepare(scene.ctx());
    };
    c.prepare(scene.ctx());
    EXPECT_FALSE(scene.test(c, "a"));  // t=1: 0 s
    at(2, 0.05, 0);
    at(3, 0.05, 0);  // b is never tested in between and still counts
    EXPECT_TRUE(scene.test(c, "a"));
    EXPECT_TRUE(scene.test(c, "b"));
    at(4, 0.1, 0);  // 0.1 m/s is not standing
    EXPECT_FALSE(scene.test(c, "a"));
    at(5, 0, 0);
    at(6, 0, 0);
    EXPECT_FALSE(scene.test(c, "a"));  // 1 s
    at(7, 0, 0);
    EXPECT_TRUE(scene.test(c, "a"));
    // A vehicle missing from a step starts again.
    scene.set({car("b", 0, 0, 0)}, SimTime::fromSeconds(8));
    c.prepare(scene.ctx());
    at(9, 0, 0);
    EXPECT_FALSE(scene.test(c, "a"));
    EXPECT_TRUE(scene.test(c, "b"));
    EXPECT_THROW(StandstillCondition(SimTime::fromSeconds(-1)), std::invalid_argument);
}

TEST(AccelerationCondition, ComparesStrictly) {
    AccelerationConditionGreater greater(1.0);
    AccelerationConditionLess less(-3.0);
    Scene scene(
        {on("a", "e_0", "car", 1.5), on("b", "e_0", "car", 1.0), on("c", "e_0", "car", -4), on("d", "e_0", "car", -3)});
    EXPECT_TRUE(scene.test(greater, "a"));
    EXPECT_FALSE(scene.test(greater, "b"));
    EXPECT_TRUE(scene.test(less, "c"));
    EXPECT_FALSE(scene.test(less, "d"));
    EXPECT_THROW(AccelerationConditionLess(std::nan("")), std::invalid_argument);
}

TEST(RoadAndLaneCondition, MatchTheGivenIds) {
    RoadCondition road({"e1", ":J3_0"});
    LaneCondition lane({"e2_1"});
    Scene scene({on("a", "e1_0"), on("b", "e2_1"), on("c", "e2_0"), on("d", ":J3_0_0")});
    EXPECT_TRUE(scene.test(road, "a"));
    EXPECT_FALSE(scene.test(road, "b"));
    EXPECT_TRUE(scene.test(road, "d"));
    EXPECT_TRUE(scene.test(lane, "b"));
    EXPECT_FALSE(scene.test(lane, "c"));
    EXPECT_FALSE(scene.test(lane, "a"));
    // A new snapshot interns its strings afresh: the verdicts must follow it.
    scene.set({on("c", "e2_1"), on("a", "e9_0")}, SimTime::fromSeconds(1));
    EXPECT_TRUE(scene.test(lane, "c"));
    EXPECT_FALSE(scene.test(road, "a"));
    EXPECT_FALSE(lane.test(scene.ctx(), scene.index("a"))) << "without prepare() too";
}

TEST(TypeCondition, MatchesTheWholeTypeId) {
    TypeCondition trucks("truck.*|bus");
    Scene scene(
        {on("a", "e_0", "truck_heavy"), on("b", "e_0", "bus"), on("c", "e_0", "minibus"), on("d", "e_0", "car")});
    EXPECT_TRUE(scene.test(trucks, "a"));
    EXPECT_TRUE(scene.test(trucks, "b"));
    EXPECT_FALSE(scene.test(trucks, "c")) << "a partial match is no match";
    EXPECT_FALSE(scene.test(trucks, "d"));
    EXPECT_TRUE(trucks.pure());
    try {
        TypeCondition bad("car(");
        FAIL() << "a bad pattern must be rejected";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("car("), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace sbsim::storyboard::test
