#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "StoryboardTestSupport.h"
#include "sbsim/storyboard/CanvasFrame.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/StoryAreas.h"
#include "sbsim/storyboard/StoryCheck.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/DistanceCondition.h"
#include "sbsim/storyboard/conditions/NotCondition.h"
#include "sbsim/storyboard/conditions/OrCondition.h"
#include "sbsim/storyboard/conditions/PolygonCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"

namespace sbsim::storyboard::test {
namespace {

using Points = std::vector<Eigen::Vector2d>;

const Points kSquare{{390, 390}, {810, 390}, {810, 810}, {390, 810}};
const Points kTriangle{{0, 0}, {100, 0}, {0, 100}};

std::shared_ptr<TimeCondition> window() {
    return std::make_shared<TimeCondition>(SimTime::fromSeconds(120), SimTime::fromSeconds(420));
}

TEST(StoryAreas, PolygonsAndPointDistancesDepthFirstInChildOrder) {
    const auto square = std::make_shared<PolygonCondition>(kSquare);
    const auto triangle = std::make_shared<PolygonCondition>(kTriangle);
    const auto near = std::make_shared<DistanceCondition>(Eigen::Vector2d(50, 60), 25.0);
    // (square ∧ t) ∨ ¬(near ∧ triangle)
    const OrCondition tree(std::make_shared<AndCondition>(square, window()),
                           std::make_shared<NotCondition>(std::make_shared<AndCondition>(near, triangle)));
    const auto areas = conditionAreas(tree);
    ASSERT_EQ(areas.size(), 3U);
    EXPECT_EQ(areas[0].condition, square.get());
    EXPECT_EQ(areas[0].points, kSquare);
    EXPECT_FALSE(areas[0].radius);
    EXPECT_EQ(areas[1].condition, near.get());
    EXPECT_EQ(areas[1].points, (Points{{50, 60}}));
    EXPECT_EQ(areas[1].radius, 25.0);
    EXPECT_EQ(areas[2].condition, triangle.get());
    EXPECT_EQ(areas[2].points, kTriangle);
}

TEST(StoryAreas, ASharedConditionYieldsItsAreaOnce) {
    // grid-rain's shape: one "raining here" node used twice in one tree.
    const auto raining = std::make_shared<AndCondition>(std::make_shared<PolygonCondition>(kSquare), window());
    const Story story(std::make_shared<OrCondition>(raining, std::make_shared<NotCondition>(raining)), {});
    const auto areas = storyAreas(story);
    ASSERT_EQ(areas.size(), 1U);
    EXPECT_EQ(areas[0].points, kSquare);
}

TEST(StoryAreas, AVehicleDistanceAndAreaFreeTreesHaveNone) {
    EXPECT_TRUE(conditionAreas(DistanceCondition("leader", 30.0)).empty());
    EXPECT_TRUE(storyAreas(Story(window(), {})).empty());
}

TEST(StoryAreas, CanvasPointsAreReportedInSumoFrame) {
    // The bindings convert Coord points with the canvas frame; the area is what the condition holds.
    const Eigen::Matrix2d boundary = (Eigen::Matrix2d() << -100, 700, -50, 650).finished();
    const CanvasFrame frame(boundary);
    Points sumo;
    for (const Eigen::Vector2d& canvas : Points{{0, 0}, {200, 0}, {200, 100}}) sumo.push_back(frame.toSumo(canvas));
    auto polygon = std::make_shared<PolygonCondition>(sumo);
    polygon->setGivenFrame(PolygonCondition::GivenFrame::Canvas);
    const auto areas = conditionAreas(*polygon);
    ASSERT_EQ(areas.size(), 1U);
    EXPECT_EQ(areas[0].points, (Points{{-100, 650}, {100, 650}, {100, 550}}));
}

TEST(StoryAreas, APolygonRemembersTheFrameItWasWrittenIn) {
    PolygonCondition polygon(kTriangle);
    EXPECT_EQ(polygon.area()->given, GivenFrame::Sumo);
    polygon.setGivenFrame(GivenFrame::Canvas);
    EXPECT_EQ(polygon.area()->given, GivenFrame::Canvas);
    EXPECT_EQ(polygon.area()->points, kTriangle);
    EXPECT_FALSE(polygon.area()->radius);
}

/// A condition the storyboard does not know: its area is found because it reports one.
class RingCondition : public Condition {
public:
    ConditionResult test(const EvaluationContext&, VehicleIndex) override { return false; }
    std::optional<ConditionArea> area() const override { return ConditionArea{{{5, 5}}, 2.0}; }
};

TEST(StoryAreas, AnyConditionThatReportsAnAreaIsDrawn) {
    const auto ring = std::make_shared<RingCondition>();
    const auto areas = conditionAreas(AndCondition(window(), std::make_shared<NotCondition>(ring)));
    ASSERT_EQ(areas.size(), 1U);
    EXPECT_EQ(areas[0].condition, ring.get());
    EXPECT_EQ(areas[0].radius, 2.0);
    EXPECT_EQ(outline(areas[0], 4).size(), 4U);
}

TEST(StoryAreas, TheCheckWarnsOnceAboutASharedPolygonOutsideTheNet) {
    const auto outside = std::make_shared<PolygonCondition>(Points{{2000, 2000}, {2100, 2000}, {2100, 2100}});
    const auto story = std::make_shared<Story>(std::make_shared<OrCondition>(outside, outside),
                                               std::vector<EffectPtr>{}, std::string("far"));
    CheckScenario scenario;
    scenario.boundary << 0, 1000, 0, 1000;
    const auto warnings = checkStories({story}, scenario);
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_EQ(warnings[0].story, "far");
    EXPECT_NE(warnings[0].message.find("outside the network boundary"), std::string::npos);
}

}  // namespace
}  // namespace sbsim::storyboard::test
