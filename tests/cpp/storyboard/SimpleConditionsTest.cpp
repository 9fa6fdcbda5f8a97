#include <gtest/gtest.h>

#include <stdexcept>

#include "StoryboardTestSupport.h"
#include "TestPrinters.h"
#include "sbsim/storyboard/conditions/CarSetCondition.h"
#include "sbsim/storyboard/conditions/PolygonCondition.h"
#include "sbsim/storyboard/conditions/SpeedCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"

namespace sbsim::storyboard::test {
namespace {

using V = Eigen::Vector2d;

TEST(TimeCondition, IsTrueFromBeginToEndInclusive) {
    TimeCondition c(SimTime::fromSeconds(10), SimTime::fromSeconds(20));
    Scene scene({car("a", 0, 0)});
    const auto at = [&](SimTime t) {
        scene.set({car("a", 0, 0)}, t);
        return scene.test(c, "a").isTrue();
    };
    EXPECT_FALSE(at(SimTime::fromSeconds(9.9)));
    EXPECT_FALSE(at(SimTime::fromSeconds(10) - SimTime::fromNanoseconds(1)));
    EXPECT_TRUE(at(SimTime::fromSeconds(10)));
    EXPECT_TRUE(at(SimTime::fromSeconds(15)));
    EXPECT_TRUE(at(SimTime::fromSeconds(20)));
    EXPECT_FALSE(at(SimTime::fromSeconds(20) + SimTime::fromNanoseconds(1)));
    EXPECT_FALSE(scene.test(c, "a").isSet());
}

TEST(TimeCondition, WithoutEndLastsForever) {
    TimeCondition c(SimTime::fromSeconds(5));
    EXPECT_EQ(c.end(), SimTime::max());
    Scene scene({car("a", 0, 0)}, SimTime::fromSeconds(4));
    EXPECT_FALSE(scene.test(c, "a"));
    scene.set({car("a", 0, 0)}, SimTime::fromSeconds(1e8));
    EXPECT_TRUE(scene.test(c, "a"));
}

TEST(TimeCondition, RejectsEndBeforeBegin) {
    EXPECT_THROW(TimeCondition(SimTime::fromSeconds(2), SimTime::fromSeconds(1)), std::invalid_argument);
    EXPECT_NO_THROW(TimeCondition(SimTime::fromSeconds(2), SimTime::fromSeconds(2)));
}

TEST(SpeedCondition, ComparisonsAreStrict) {
    SpeedConditionGreater greater(10);
    SpeedConditionLess less(10);
    Scene scene({car("at", 0, 0, 10), car("above", 0, 50, 10.000001), car("below", 0, 100, 9.999999)});
    EXPECT_FALSE(scene.test(greater, "at"));
    EXPECT_TRUE(scene.test(greater, "above"));
    EXPECT_FALSE(scene.test(greater, "below"));
    EXPECT_FALSE(scene.test(less, "at"));
    EXPECT_FALSE(scene.test(less, "above"));
    EXPECT_TRUE(scene.test(less, "below"));
    EXPECT_THROW(SpeedConditionGreater(std::nan("")), std::invalid_argument);
}

TEST(CarSetCondition, MatchesTheListedIds) {
    CarSetCondition c({"b", "flow.7"});
    Scene scene({car("a", 0, 0), car("b", 1, 0), car("flow.7", 2, 0), car("flow.70", 3, 0)});
    EXPECT_FALSE(scene.test(c, "a"));
    EXPECT_TRUE(scene.test(c, "b"));
    EXPECT_TRUE(scene.test(c, "flow.7"));
    EXPECT_FALSE(scene.test(c, "flow.70"));
    CarSetCondition none({});
    EXPECT_FALSE(scene.test(none, "b"));
}

TEST(CarSetCondition, FlagsMadeOncePerIdListAndOnlyForIt) {
    // prepare() looks the ids up once per id list; test() reads the flags only for that list.
    CarSetCondition c({"b", "d"});
    traffic::VehicleSnapshot first;
    first.assign({car("a", 0, 0), car("b", 1, 0), car("c", 2, 0)}, SimTime::fromSeconds(1));
    traffic::NeighbourGrid grid;
    grid.build(first, 100);
    const EvaluationContext ctx(first, grid);
    EXPECT_FALSE(c.flagsFor(first));
    c.prepare(ctx);
    EXPECT_TRUE(c.flagsFor(first));
    EXPECT_EQ(c.test(ctx, 0).isTrue(), false);
    EXPECT_EQ(c.test(ctx, 1).isTrue(), true);
    EXPECT_EQ(c.test(ctx, 2).isTrue(), false);

    // The same vehicles a step later (the snapshot refilled, its id list kept) keep their flags.
    first.assign({car("c", 5, 0), car("b", 6, 0), car("a", 7, 0)}, SimTime::fromSeconds(2));
    EXPECT_TRUE(c.flagsFor(first));
    EXPECT_EQ(c.test(ctx, 1).isTrue(), true);

    // Another list of the same length, unprepared: answered by its own ids, not the old flags.
    traffic::VehicleSnapshot other;
    other.assign({car("b", 0, 0), car("c", 1, 0), car("d", 2, 0)}, SimTime::fromSeconds(2));
    traffic::NeighbourGrid otherGrid;
    otherGrid.build(other, 100);
    const EvaluationContext otherCtx(other, otherGrid);
    EXPECT_FALSE(c.flagsFor(other));
    EXPECT_EQ(c.test(otherCtx, 0).isTrue(), true);
    EXPECT_EQ(c.test(otherCtx, 1).isTrue(), false);
    EXPECT_EQ(c.test(otherCtx, 2).isTrue(), true);
    c.prepare(otherCtx);
    EXPECT_TRUE(c.flagsFor(other));
    EXPECT_EQ(c.test(otherCtx, 0).isTrue(), true);
    EXPECT_EQ(c.test(otherCtx, 1).isTrue(), false);
    EXPECT_EQ(c.test(otherCtx, 2).isTrue(), true);
}

TEST(PolygonCondition, UsesTheFrontBumperAndExcludesTheBoundary) {
    PolygonCondition c({V(0, 0), V(100, 0), V(100, 50), V(0, 50)});
    Scene scene({
        car("inside", 50, 25),
        car("outside", 150, 25),
        car("onEdge", 100, 25),
        car("onCorner", 0, 0),
        // Front bumper just inside, most of the body outside (driving north into the area).
        car("entering", 50, 0.5, 10, 0),
        // Front bumper just out, body still inside.
        car("leaving", 50, 50.5, 10, 0),
    });
    EXPECT_TRUE(scene.test(c, "inside"));
    EXPECT_FALSE(scene.test(c, "outside"));
    EXPECT_FALSE(scene.test(c, "onEdge"));
    EXPECT_FALSE(scene.test(c, "onCorner"));
    EXPECT_TRUE(scene.test(c, "entering"));
    EXPECT_FALSE(scene.test(c, "leaving"));
}

TEST(PolygonCondition, NonConvexArea) {
    PolygonCondition c({V(0, 0), V(30, 0), V(30, 30), V(20, 30), V(20, 10), V(10, 10), V(10, 30), V(0, 30)});
    Scene scene({car("arm", 5, 20), car("notch", 15, 20), car("base", 15, 5)});
    EXPECT_TRUE(scene.test(c, "arm"));
    EXPECT_FALSE(scene.test(c, "notch"));
    EXPECT_TRUE(scene.test(c, "base"));
}

TEST(PolygonCondition, RejectsFewerThanThreeVertices) {
    EXPECT_THROW(PolygonCondition({V(0, 0), V(1, 1)}), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::storyboard::test
