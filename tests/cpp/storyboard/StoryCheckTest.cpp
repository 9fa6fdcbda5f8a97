// What `sbsim check` learns by asking the nodes of a story: each condition and effect describes
// itself, says whether it looks at time only and which time window bounds it, and reports its own
// warnings through the check hook; checkStories only walks the tree.

#include <gtest/gtest.h>

#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "sbsim/kernel/RandomStream.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/CheckContext.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/StoryCheck.h"
#include "sbsim/storyboard/WorldStory.h"
#include "sbsim/storyboard/conditions/AccelerationCondition.h"
#include "sbsim/storyboard/conditions/AllCondition.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/AnyCondition.h"
#include "sbsim/storyboard/conditions/CarSetCondition.h"
#include "sbsim/storyboard/conditions/CollisionCondition.h"
#include "sbsim/storyboard/conditions/DeferringCondition.h"
#include "sbsim/storyboard/conditions/DistanceCondition.h"
#include "sbsim/storyboard/conditions/EquippedCondition.h"
#include "sbsim/storyboard/conditions/HeadwayCondition.h"
#include "sbsim/storyboard/conditions/HoldCondition.h"
#include "sbsim/storyboard/conditions/LaneCondition.h"
#include "sbsim/storyboard/conditions/LatchCondition.h"
#include "sbsim/storyboard/conditions/LikelihoodCondition.h"
#include "sbsim/storyboard/conditions/LimitCondition.h"
#include "sbsim/storyboard/conditions/NotCondition.h"
#include "sbsim/storyboard/conditions/OrCondition.h"
#include "sbsim/storyboard/conditions/PolygonCondition.h"
#include "sbsim/storyboard/conditions/RelativeDistanceCondition.h"
#include "sbsim/storyboard/conditions/RisingCondition.h"
#include "sbsim/storyboard/conditions/RoadCondition.h"
#include "sbsim/storyboard/conditions/SpeedCondition.h"
#include "sbsim/storyboard/conditions/SpeedDifferenceCondition.h"
#include "sbsim/storyboard/conditions/StandstillCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/conditions/TrafficSignalCondition.h"
#include "sbsim/storyboard/conditions/TraveledDistanceCondition.h"
#include "sbsim/storyboard/conditions/TtcCondition.h"
#include "sbsim/storyboard/conditions/TypeCondition.h"
#include "sbsim/storyboard/criteria/WarnedBefore.h"
#include "sbsim/storyboard/effects/CloseRoadEffect.h"
#include "sbsim/storyboard/effects/ColorEffect.h"
#include "sbsim/storyboard/effects/EmergencyStopEffect.h"
#include "sbsim/storyboard/effects/LaneChangeEffect.h"
#include "sbsim/storyboard/effects/LaneEffect.h"
#include "sbsim/storyboard/effects/LaneOffsetEffect.h"
#include "sbsim/storyboard/effects/RouteEffect.h"
#include "sbsim/storyboard/effects/SignalEffect.h"
#include "sbsim/storyboard/effects/SpawnEffect.h"
#include "sbsim/storyboard/effects/SpeedChangeEffect.h"
#include "sbsim/storyboard/effects/SpeedEffect.h"
#include "sbsim/storyboard/effects/SpeedFactorEffect.h"
#include "sbsim/storyboard/effects/StopEffect.h"
#include "sbsim/storyboard/effects/TrafficLightEffect.h"
#include "sbsim/storyboard/effects/TypeEffect.h"

namespace sbsim::storyboard {
namespace {

using kernel::SimTime;
using Ids = std::set<std::string>;

SimTime s(double seconds) { return SimTime::fromSeconds(seconds); }
std::shared_ptr<TimeCondition> window(double begin, double end) {
    return std::make_shared<TimeCondition>(s(begin), s(end));
}
std::shared_ptr<kernel::RandomStream> rng() { return std::make_shared<kernel::RandomStream>(1, 0); }

/// A scenario of 0..100 s whose network has edges "a", "b" (and ":J_0"), lanes "a_0", light "J",
/// type "car", and whose route files define vehicle "v1".
CheckScenario scenario() {
    CheckScenario out;
    out.boundary << 0, 1000, 0, 1000;
    out.begin = s(0);
    out.end = s(100);
    const auto in = [](Ids ids) {
        return [ids = std::move(ids)](std::string_view id) { return ids.contains(std::string(id)); };
    };
    out.vehicleDefined = in({"v1"});
    out.edgeExists = in({"a", "b", ":J_0"});
    out.laneExists = in({"a_0"});
    out.trafficLightExists = in({"J"});
    out.vehicleTypeExists = in({"car"});
    return out;
}

std::vector<std::string> messages(const std::vector<StoryPtr>& stories, const CheckScenario& sc = scenario()) {
    std::vector<std::string> out;
    for (const CheckWarning& w : checkStories(stories, sc)) out.push_back(w.story + ": " + w.message);
    return out;
}

StoryPtr story(ConditionPtr c, std::vector<EffectPtr> effects = {}, std::string name = "s") {
    return std::make_shared<Story>(std::move(c), std::move(effects), std::move(name));
}
StoryPtr worldStory(ConditionPtr c, std::vector<WorldEffectPtr> effects, std::string name = "w") {
    return std::make_shared<WorldStory>(std::move(c), std::move(effects), std::move(name));
}

TEST(StoryCheck, EveryConditionDescribesItselfWithItsArguments) {
    const std::vector<std::pair<ConditionPtr, std::string>> cases{
        {window(120, 420), "TimeCondition(120 s, 420 s)"},
        {std::make_shared<TimeCondition>(s(5)), "TimeCondition(5 s, end)"},
        {std::make_shared<SpeedConditionGreater>(13.9), "SpeedConditionGreater(13.9 m/s)"},
        {std::make_shared<SpeedConditionLess>(2), "SpeedConditionLess(2 m/s)"},
        {std::make_shared<PolygonCondition>(std::vector<Eigen::Vector2d>{{0, 0}, {10, 0}, {0, 5.5}}),
         "PolygonCondition(3 points, SUMO frame: (0, 0) (10, 0) (0, 5.5))"},
        {std::make_shared<CarSetCondition>(Ids{"c", "a", "b", "d", "e", "f"}), "CarSetCondition(a, b, c, d, e, … (6))"},
        {std::make_shared<LimitCondition>(3), "LimitCondition(3)"},
        {std::make_shared<SpeedDifferenceConditionFaster>(5, 50), "SpeedDifferenceConditionFaster(5 m/s, within 50 m)"},
        {std::make_shared<SpeedDifferenceConditionSlower>(2), "SpeedDifferenceConditionSlower(2 m/s)"},
        {std::make_shared<TtcCondition>(3, 80), "TtcCondition(3 s, within 80 m)"},
        {std::make_shared<DistanceCondition>(Eigen::Vector2d(1, 2), 25), "DistanceCondition((1, 2), 25 m)"},
        {std::make_shared<DistanceCondition>("lead", 30), "DistanceCondition(vehicle lead, 30 m)"},
        {std::make_shared<HeadwayCondition>(1.5), "HeadwayCondition(1.5 s)"},
        {std::make_shared<HoldCondition>(window(0, 9), s(2)), "HoldCondition(2 s)"},
        {std::make_shared<StandstillCondition>(s(30)), "StandstillCondition(30 s)"},
        {std::make_shared<LikelihoodCondition>(rng(), 0.25), "LikelihoodCondition(0.25)"},
        {std::make_shared<DeferringCondition>(rng(), s(1), s(4)), "DeferringCondition(1 s to 4 s)"},
        {std::make_shared<AccelerationConditionGreater>(1), "AccelerationConditionGreater(1 m/s²)"},
        {std::make_shared<AccelerationConditionLess>(-4.5), "AccelerationConditionLess(-4.5 m/s²)"},
        {std::make_shared<TypeCondition>("truck.*"), "TypeCondition('truck.*')"},
        {std::make_shared<RoadCondition>(Ids{"c3", "b12"}), "RoadCondition(b12, c3)"},
        {std::make_shared<LaneCondition>(Ids{"b12_0"}), "LaneCondition(b12_0)"},
        {std::make_shared<CollisionCondition>(), "CollisionCondition"},
        {std::make_shared<EquippedCondition>(), "EquippedCondition()"},
        {std::make_shared<TraveledDistanceCondition>(250), "TraveledDistanceCondition(250 m)"},
        {std::make_shared<TrafficSignalCondition>("J", "GrGr"), "TrafficSignalCondition('J' shows 'GrGr')"},
        {std::make_shared<TrafficSignalCondition>("J", "r", std::vector<int>{2}),
         "TrafficSignalCondition('J' link 2 shows 'r')"},
        {std::make_shared<RelativeDistanceCondition>("lead", 20, ComparisonRule::LessThan,
                                                     RelativeDistanceCondition::Kind::Longitudinal, true),
         "RelativeDistanceCondition(vehicle lead, longitudinal freespace, lessThan 20 m)"},
        {std::make_shared<RelativeDistanceCondition>("lead", 3.5, ComparisonRule::GreaterOrEqual,
                                                     RelativeDistanceCondition::Kind::Cartesian, false),
         "RelativeDistanceCondition(vehicle lead, cartesian reference points, greaterOrEqual 3.5 m)"},
        // Logic nodes are their name: their operands are printed below them.
        {std::make_shared<NotCondition>(window(0, 1)), "NotCondition"},
        {std::make_shared<AllCondition>(std::vector<ConditionPtr>{window(0, 1)}), "AllCondition"},
    };
    for (const auto& [condition, text] : cases) EXPECT_EQ(condition->describe(), text);
}

TEST(StoryCheck, EveryEffectDescribesItselfWithItsArguments) {
    const std::vector<std::pair<EffectPtr, std::string>> cases{
        {std::make_shared<SpeedEffect>(5), "SpeedEffect(5 m/s)"},
        {std::make_shared<SpeedFactorEffect>(0.8), "SpeedFactorEffect(0.8)"},
        {std::make_shared<SignalEffect>("rain"), "SignalEffect('rain')"},
        {std::make_shared<SignalEffect>("rain", "dry"), "SignalEffect('rain', on exit 'dry')"},
        {std::make_shared<TypeEffect>("truck"), "TypeEffect('truck')"},
        {std::make_shared<LaneEffect>(1), "LaneEffect(1)"},
        {std::make_shared<RouteEffect>("e9", std::vector<std::string>{}), "RouteEffect(to e9)"},
        {std::make_shared<RouteEffect>(std::nullopt, std::vector<std::string>{"a", "b"}), "RouteEffect(via a, b)"},
        {std::make_shared<ColorEffect>(traffic::Color{255, 0, 0}), "ColorEffect(255, 0, 0)"},
        {std::make_shared<ColorEffect>(traffic::Color{1, 2, 3, 4}), "ColorEffect(1, 2, 3, 4)"},
        {std::make_shared<StopEffect>(), "StopEffect"},
        {std::make_shared<EmergencyStopEffect>(), "EmergencyStopEffect"},
        {std::make_shared<SpeedChangeEffect>(
             20, traffic::Transition{traffic::Transition::Shape::Linear, traffic::Transition::Dimension::Time, 4}),
         "SpeedChangeEffect(20 m/s, linear over 4 s)"},
        {std::make_shared<SpeedChangeEffect>(
             -5, traffic::Transition{traffic::Transition::Shape::Cubic, traffic::Transition::Dimension::Rate, 2},
             "lead", traffic::SpeedTarget::Kind::Delta, true, true),
         "SpeedChangeEffect(lead's speed -5 m/s, continuous, cubic at 2 m/s², safe gap)"},
        {std::make_shared<SpeedChangeEffect>(0.5, traffic::Transition{}, "lead", traffic::SpeedTarget::Kind::Factor),
         "SpeedChangeEffect(lead's speed x 0.5, step)"},
        {std::make_shared<LaneChangeEffect>(
             1, traffic::Transition{traffic::Transition::Shape::Sinusoidal, traffic::Transition::Dimension::Time, 3}),
         "LaneChangeEffect(lane 1, sinusoidal over 3 s)"},
        {std::make_shared<LaneChangeEffect>(
             -1, traffic::Transition{traffic::Transition::Shape::Linear, traffic::Transition::Dimension::Distance, 60},
             LaneChangeEffect::Relative::Vehicle, "lead", 0.5),
         "LaneChangeEffect(lead's lane -1 +0.5 m, linear over 60 m)"},
        {std::make_shared<LaneChangeEffect>(1, traffic::Transition{}, LaneChangeEffect::Relative::Self),
         "LaneChangeEffect(own lane +1, step)"},
        {std::make_shared<LaneOffsetEffect>(
             0.6, traffic::Transition{traffic::Transition::Shape::Cubic, traffic::Transition::Dimension::Time, 2},
             std::nullopt),
         "LaneOffsetEffect(+0.6 m, cubic over 2 s)"},
        {std::make_shared<LaneOffsetEffect>(
             -0.4, traffic::Transition{traffic::Transition::Shape::Sinusoidal, traffic::Transition::Dimension::Time, 1},
             0.5),
         "LaneOffsetEffect(-0.4 m, sinusoidal at most 0.5 m/s²)"},
    };
    for (const auto& [effect, text] : cases) EXPECT_EQ(effect->describe(), text);
    SpawnEffect::Spec spec;
    spec.id = "x";
    spec.from = "a";
    spec.to = "b";
    spec.type = "bus";
    EXPECT_EQ(SpawnEffect(spec).describe(), "SpawnEffect('x', a to b, type bus)");
    EXPECT_EQ(SpawnEffect(spec).definedVehicles(), (std::vector<std::string>{"x"}));
    EXPECT_TRUE(CloseRoadEffect({"a"}).definedVehicles().empty());
}

TEST(StoryCheck, LogicNodesAreTimeOnlyExactlyWhenTheirOperandsAre) {
    const ConditionPtr t = window(0, 10);
    const ConditionPtr speed = std::make_shared<SpeedConditionGreater>(1);
    EXPECT_TRUE(t->timeOnly());
    EXPECT_FALSE(speed->timeOnly());
    EXPECT_FALSE(std::make_shared<CarSetCondition>(Ids{"a"})->timeOnly());
    EXPECT_TRUE(AndCondition(t, std::make_shared<NotCondition>(t)).timeOnly());
    EXPECT_FALSE(AndCondition(t, speed).timeOnly());
    EXPECT_FALSE(OrCondition(speed, t).timeOnly());
    EXPECT_TRUE(AllCondition({t, t, std::make_shared<RisingCondition>(t)}).timeOnly());
    EXPECT_FALSE(AnyCondition({t, std::make_shared<HoldCondition>(speed, s(1))}).timeOnly());
    EXPECT_TRUE(AnyCondition({t, std::make_shared<HoldCondition>(t, s(1))}).timeOnly());
    EXPECT_TRUE(LatchCondition(t).timeOnly());
    EXPECT_FALSE(LatchCondition(speed).timeOnly());
}

TEST(StoryCheck, ConjunctionsIntersectTheirOperandsTimeWindows) {
    const ConditionPtr speed = std::make_shared<SpeedConditionGreater>(1);
    const auto w = AndCondition(window(10, 50), std::make_shared<AndCondition>(speed, window(30, 90))).timeWindow();
    ASSERT_TRUE(w);
    EXPECT_EQ(w->begin, s(30));
    EXPECT_EQ(w->end, s(50));
    EXPECT_FALSE(AndCondition(speed, speed).timeWindow());
    EXPECT_FALSE(OrCondition(window(0, 1), window(2, 3)).timeWindow());  // a disjunction is not bounded by either
    EXPECT_TRUE(AllCondition({window(0, 10), window(20, 30)}).timeWindow()->empty());
}

TEST(StoryCheck, EachConditionReportsItsOwnMistakes) {
    const auto speed = std::make_shared<SpeedConditionGreater>(1);
    EXPECT_EQ(messages({story(window(200, 300), {}, "late"), story(window(50, 60), {}, "fine")}),
              (std::vector<std::string>{"late: TimeCondition(200 s, 300 s) lies outside the run (0 s to 100 s)"}));
    EXPECT_EQ(messages({story(std::make_shared<LimitCondition>(0)), story(std::make_shared<LimitCondition>(1))}),
              (std::vector<std::string>{"s: LimitCondition(0) admits no vehicle: the story never activates"}));
    EXPECT_EQ(messages({story(std::make_shared<AndCondition>(window(0, 10),
                                                             std::make_shared<AndCondition>(speed, window(20, 30))))}),
              (std::vector<std::string>{"s: AndCondition can never hold: its time windows do not overlap"}));
    EXPECT_EQ(messages({story(std::make_shared<AndCondition>(speed, window(20, 30)))}), std::vector<std::string>{});
}

TEST(StoryCheck, CarSetIdsAreDefinedByRouteFilesOrByAStorysSpawn) {
    SpawnEffect::Spec spec;
    spec.id = "spawned";
    spec.route = {"a", "b"};
    const auto cars = std::make_shared<CarSetCondition>(Ids{"v1", "spawned", "ghost"});
    EXPECT_EQ(messages({story(cars), worldStory(window(1, 2), {std::make_shared<SpawnEffect>(spec)})}),
              (std::vector<std::string>{"s: CarSetCondition names vehicles no route file defines: ghost"}));
    CheckScenario blind = scenario();
    blind.vehicleDefined = nullptr;  // no route files read: nothing to say
    EXPECT_EQ(messages({story(cars)}, blind), std::vector<std::string>{});
}

TEST(StoryCheck, IdsTheNetworkLacksAreWarnedByTheNodeThatNamesThem) {
    SpawnEffect::Spec spec;
    spec.id = "x";
    spec.from = "a";
    spec.to = "zz";
    spec.type = "hovercraft";
    const std::vector<StoryPtr> stories{
        story(std::make_shared<RoadCondition>(Ids{"a", ":J_0", "nowhere"}), {std::make_shared<TypeEffect>("car")},
              "road"),
        story(std::make_shared<LaneCondition>(Ids{"a_0", "a_7"}), {std::make_shared<TypeEffect>("bus")}, "lane"),
        story(window(1, 2), {std::make_shared<RouteEffect>(std::nullopt, std::vector<std::string>{"b", "qq"})},
              "route"),
        worldStory(std::make_shared<TrafficSignalCondition>("L", "r"), {}, "signal"),
        worldStory(window(1, 2), {std::make_shared<CloseRoadEffect>(std::vector<std::string>{"a", "gone"}),
                                  std::make_shared<TrafficLightEffect>("K", "r"),
                                  std::make_shared<TrafficLightEffect>("J", "r"), std::make_shared<SpawnEffect>(spec)}),
    };
    EXPECT_EQ(messages(stories), (std::vector<std::string>{
                                     "road: RoadCondition names edges the network does not have: nowhere",
                                     "lane: LaneCondition names lanes the network does not have: a_7",
                                     "lane: TypeEffect names vehicle types SUMO did not load: bus",
                                     "route: RouteEffect names edges the network does not have: qq",
                                     "signal: TrafficSignalCondition names traffic lights the network does not have: L",
                                     "w: CloseRoadEffect names edges the network does not have: gone",
                                     "w: TrafficLightEffect names traffic lights the network does not have: K",
                                     "w: SpawnEffect names edges the network does not have: zz",
                                     "w: SpawnEffect names vehicle types SUMO did not load: hovercraft",
                                 }));
    // Without a loaded network there is nothing to compare with.
    CheckScenario blind;
    blind.end = s(100);
    EXPECT_EQ(messages(stories, blind), std::vector<std::string>{});
}

TEST(StoryCheck, CriteriaReportTheIdsTheyNameThatTheNetworkLacks) {
    const std::vector<CriterionPtr> criteria{
        WarnedBefore::onEdge("a", std::nullopt, s(0), s(0), std::nullopt),
        WarnedBefore::onEdge("nowhere", std::nullopt, s(0), s(0), std::nullopt),
    };
    criteria[1]->setName("warned");
    const auto warnings = checkCriteria(criteria, scenario());
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].story, "warned");
    EXPECT_EQ(warnings[0].message, "WarnedBefore names edges the network does not have: nowhere");
    EXPECT_TRUE(warnings[0].unknownId);
}

TEST(StoryCheck, UnknownIdsAreMarkedForARunToRefuseAndOtherWarningsAreNot) {
    // A run refuses a story whose warning names a missing id; the other warnings stay warnings.
    const auto warnings = checkStories(
        {story(std::make_shared<RoadCondition>(Ids{"nowhere"})), story(window(200, 300), {}, "late")}, scenario());
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_TRUE(warnings[0].unknownId);
    EXPECT_FALSE(warnings[1].unknownId);
}

TEST(StoryCheck, EffectsOfOneDomainInOneStoryAreWarnedAbout) {
    const auto t = window(1, 2);
    EXPECT_EQ(messages({story(t, {std::make_shared<SpeedEffect>(5), std::make_shared<SpeedFactorEffect>(0.5),
                                  std::make_shared<EmergencyStopEffect>()})}),
              (std::vector<std::string>{"s: effects of the same domain (speed) in one story: SpeedEffect(5 m/s), "
                                        "EmergencyStopEffect (the last applied rules)"}));
    EXPECT_EQ(messages({story(t, {std::make_shared<ColorEffect>(traffic::Color{}), std::make_shared<LaneEffect>(0),
                                  std::make_shared<TypeEffect>("car")})}),
              std::vector<std::string>{});
}

TEST(StoryCheck, ASharedNodeReportsOncePerStory) {
    const auto late = window(200, 300);
    EXPECT_EQ(messages({story(std::make_shared<OrCondition>(late, std::make_shared<NotCondition>(late)))}),
              (std::vector<std::string>{"s: TimeCondition(200 s, 300 s) lies outside the run (0 s to 100 s)"}));
}

TEST(StoryCheck, AStoryAnswersWhetherItActsOnTheNetwork) {
    const auto plain = story(window(1, 2));
    const auto close = std::make_shared<CloseRoadEffect>(std::vector<std::string>{"a"});
    const auto world = worldStory(window(1, 2), {close});
    EXPECT_FALSE(plain->isWorldStory());
    EXPECT_TRUE(plain->worldEffects().empty());
    EXPECT_TRUE(world->isWorldStory());
    EXPECT_EQ(world->worldEffects(), (std::vector<WorldEffectPtr>{close}));
}

}  // namespace
}  // namespace sbsim::storyboard
