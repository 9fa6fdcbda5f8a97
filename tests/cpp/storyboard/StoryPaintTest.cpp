// What `sbsim --gui` shows of the stories without a display: the palette, the story colours
// composed on each vehicle's effect stack (StoryPainter, watching the board's activations), and the areas drawn.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "StoryboardTestSupport.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/storyboard/StoryAreas.h"
#include "sbsim/storyboard/StoryPainter.h"
#include "sbsim/storyboard/StoryPalette.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/DistanceCondition.h"
#include "sbsim/storyboard/conditions/PolygonCondition.h"
#include "sbsim/storyboard/conditions/SpeedCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/effects/ColorEffect.h"

namespace sbsim::storyboard {
namespace {

using kernel::SimTime;
using traffic::Color;
using traffic::VehicleSnapshot;

constexpr Color kOwn{255, 255, 0, 255};  // SUMO's default vehicle yellow
constexpr Color kRed{255, 0, 0, 255};

auto rgba(const Color& c) { return std::make_tuple(c.r, c.g, c.b, c.a); }

/// Every colour command per vehicle; vehicles start in kOwn.
struct Paintings {
    std::map<std::string, Color> now;
    std::map<std::string, std::vector<Color>> commands;
};

class PaintedVehicle : public traffic::VehicleController {
public:
    PaintedVehicle(const std::string& id, Paintings& log) : VehicleController(id), log_(log) {
        log_.now.try_emplace(id, kOwn);
    }
    Color color() const override { return log_.now.at(id()); }
    void setColor(const Color& c) override {
        log_.now[id()] = c;
        log_.commands[id()].push_back(c);
    }

private:
    Paintings& log_;
};

TEST(StoryPalette, TenDistinctColoursInMatplotlibsOrderThenRepeats) {
    EXPECT_EQ(rgba(storyColour(0)), rgba(Color{31, 119, 180, 255}));  // matplotlib's C0
    EXPECT_EQ(rgba(storyColour(1)), rgba(Color{255, 127, 14, 255}));  // C1
    std::set<std::tuple<int, int, int, int>> seen;
    for (std::size_t i = 0; i < 10; ++i) {
        seen.insert(rgba(storyColour(i)));
        EXPECT_EQ(storyColour(i).a, 255);
        EXPECT_EQ(rgba(storyColour(i + 10)), rgba(storyColour(i)));
    }
    EXPECT_EQ(seen.size(), 10u);
    EXPECT_FALSE(seen.contains(rgba(kOwn)));
}

using test::car;

class StoryPaintTest : public testing::Test {
protected:
    StoryPaintTest() : board(sim.emplaceModule<Storyboard>(registry)) {
        registry.setControllerFactory(
            [this](const std::string& id) { return std::make_unique<PaintedVehicle>(id, paintings); });
    }
    void story(ConditionPtr condition, std::vector<EffectPtr> effects = {}) {
        board.registerStory(std::make_shared<Story>(std::move(condition), std::move(effects)));
    }
    void step(double t, std::vector<VehicleSnapshot::Vehicle> vehicles) {
        snapshot.assign(std::move(vehicles), SimTime::fromSeconds(t));
        board.update(snapshot, {});
    }
    Color colour(const std::string& id) const { return paintings.now.at(id); }

    StoryPainter painter;
    traffic::VehicleRegistry registry;

    kernel::Simulation sim{7};
    Storyboard& board;
    Paintings paintings;
    VehicleSnapshot snapshot;
};

TEST_F(StoryPaintTest, AVehicleTakesItsStorysColourWhileActiveThenItsOwnAgain) {
    board.observeActivations(painter);
    story(std::make_shared<SpeedConditionLess>(100.0));  // always: never painted by it
    story(std::make_shared<SpeedConditionGreater>(5.0));
    step(1, {car("a", 1)});
    EXPECT_EQ(rgba(colour("a")), rgba(storyColour(0)));
    step(2, {car("a", 10)});  // the second story activates later: its colour wins
    EXPECT_EQ(rgba(colour("a")), rgba(storyColour(1)));
    step(3, {car("a", 1)});  // it ends: the first story's colour comes back
    EXPECT_EQ(rgba(colour("a")), rgba(storyColour(0)));
    EXPECT_EQ(paintings.commands.at("a").size(), 3u);
}

TEST_F(StoryPaintTest, TheOwnColourComesBackWhenNoStoryIsActive) {
    board.observeActivations(painter);
    story(std::make_shared<SpeedConditionGreater>(5.0));
    step(1, {car("a", 10), car("b", 1)});
    EXPECT_EQ(rgba(colour("a")), rgba(storyColour(0)));
    EXPECT_FALSE(paintings.now.contains("b"));  // never asked, never commanded
    step(2, {car("a", 1), car("b", 1)});
    EXPECT_EQ(rgba(colour("a")), rgba(kOwn));
    EXPECT_EQ(paintings.commands.at("a").size(), 2u);
}

TEST_F(StoryPaintTest, AColorEffectOfTheStoryWinsOverItsPaintAndBothGoAtTheEnd) {
    board.observeActivations(painter);
    story(std::make_shared<SpeedConditionGreater>(5.0), {std::make_shared<ColorEffect>(kRed)});
    step(1, {car("a", 10)});
    EXPECT_EQ(rgba(colour("a")), rgba(kRed));
    step(2, {car("a", 1)});
    EXPECT_EQ(rgba(colour("a")), rgba(kOwn));
}

TEST_F(StoryPaintTest, AnOlderStorysColorEffectYieldsToANewerStorysPaint) {
    board.observeActivations(painter);
    story(std::make_shared<SpeedConditionGreater>(5.0), {std::make_shared<ColorEffect>(kRed)});
    story(std::make_shared<SpeedConditionGreater>(8.0));
    step(1, {car("a", 6)});
    step(2, {car("a", 10)});
    EXPECT_EQ(rgba(colour("a")), rgba(storyColour(1)));
    step(3, {car("a", 6)});
    EXPECT_EQ(rgba(colour("a")), rgba(kRed));
}

TEST_F(StoryPaintTest, WithoutPaintingNoColourIsCommanded) {
    story(std::make_shared<SpeedConditionGreater>(5.0));
    step(1, {car("a", 10)});
    step(2, {car("a", 1)});
    EXPECT_TRUE(paintings.commands.empty());
}

std::vector<Eigen::Vector2d> square(double x0, double y0, double side) {
    return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

TEST(StoryAreas, OutlinesArePolygonsAsGivenAndCirclesAsPointsOnThem) {
    auto district = std::make_shared<PolygonCondition>(square(390, 390, 420));
    auto near = std::make_shared<DistanceCondition>(Eigen::Vector2d(100, 200), 30.0);
    const Story rain(std::make_shared<AndCondition>(district, near), std::vector<EffectPtr>{}, "rain");
    const std::vector<StoryArea> areas = storyAreas(rain);
    ASSERT_EQ(areas.size(), 2u);
    EXPECT_EQ(outline(areas[0]), square(390, 390, 420));
    const std::vector<Eigen::Vector2d> circle = outline(areas[1], 12);
    ASSERT_EQ(circle.size(), 12u);
    for (const Eigen::Vector2d& p : circle) EXPECT_NEAR((p - Eigen::Vector2d(100, 200)).norm(), 30.0, 1e-9);
}

}  // namespace
}  // namespace sbsim::storyboard
