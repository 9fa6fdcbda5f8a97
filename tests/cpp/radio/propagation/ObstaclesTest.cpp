#include <gtest/gtest.h>

#include <cmath>

#include "sbsim/radio/propagation/Obstacles.h"

namespace sbsim::radio {
namespace {

Obstacles::Shape square(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}};
}

TEST(Obstacles, ALinkThroughABuildingLosesWallsAndDepth) {
    Obstacles o(9, 0.4);
    o.add(square(40, -10, 60, 10));  // 20 m deep along x
    const Obstacles::Crossing through = o.crossing({0, 0}, {100, 0});
    EXPECT_EQ(through.walls, 2);
    EXPECT_NEAR(through.insideMetres, 20, 1e-9);
    EXPECT_NEAR(o.lossDb({0, 0}, {100, 0}), 2 * 9 + 20 * 0.4, 1e-9);
    // Diagonally through the corner region: still two walls, the chord's length inside.
    EXPECT_NEAR(o.crossing({30, -20}, {70, 20}).insideMetres, std::sqrt(2.0) * 20, 1e-9);
}

TEST(Obstacles, FromInsideCrossesOneWall) {
    Obstacles o(9, 0.4);
    o.add(square(40, -10, 60, 10));
    const Obstacles::Crossing out = o.crossing({50, 0}, {100, 0});
    EXPECT_EQ(out.walls, 1);
    EXPECT_NEAR(out.insideMetres, 10, 1e-9);
}

TEST(Obstacles, LinksBesideOrShortOfABuildingLoseNothing) {
    Obstacles o(9, 0.4);
    o.add(square(40, -10, 60, 10));
    o.add(square(200, 200, 220, 230));
    EXPECT_EQ(o.size(), 2u);
    EXPECT_EQ(o.lossDb({0, 20}, {100, 20}), 0.0);
    EXPECT_EQ(o.lossDb({0, 0}, {30, 0}), 0.0);
    EXPECT_NEAR(o.lossDb({0, 0}, {300, -300}), 0.0, 1e-9);
    // The diagonal to (300, 300) crosses the second one corner to corner: 20√2 m inside.
    EXPECT_NEAR(o.lossDb({0, 0}, {300, 300}), 2 * 9 + 20 * std::sqrt(2.0) * 0.4, 1e-9);
    EXPECT_NEAR(o.lossDb({30, 0}, {250, 0}), 2 * 9 + 20 * 0.4, 1e-9);
}

}  // namespace
}  // namespace sbsim::radio
