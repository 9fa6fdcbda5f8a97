#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

/// A built-up city: blocks of buildings of 3 to 9 walls, convex or not, some overlapping, some
/// sharing walls, some tiny, a few far out; fixed seed.
Obstacles::Shape building(std::mt19937_64& rng, double cx, double cy) {
    std::uniform_real_distribution<double> radius(1, 30), jitter(0.3, 1.0);
    std::uniform_int_distribution<int> corners(3, 9);
    const int n = corners(rng);
    const double r = radius(rng);
    Obstacles::Shape shape;
    for (int k = 0; k < n; ++k) {
        const double angle = 2 * M_PI * k / n;
        const double rk = r * jitter(rng);  // uneven radii: concave outlines
        shape.push_back({cx + rk * std::cos(angle), cy + rk * std::sin(angle)});
    }
    return shape;
}

void expectSame(const Obstacles& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Obstacles::Crossing grid = o.crossing(a, b);
    const Obstacles::Crossing every = o.crossingEveryBuilding(a, b);
    // Exactly: the grid must find every building the walk finds and sum them in the same order.
    ASSERT_EQ(grid.walls, every.walls) << a.transpose() << " -> " << b.transpose();
    ASSERT_EQ(grid.insideMetres, every.insideMetres) << a.transpose() << " -> " << b.transpose();
    // The same from either end, to the bit: a pair's loss serves both ways within a step.
    const Obstacles::Crossing back = o.crossing(b, a);
    ASSERT_EQ(back.walls, grid.walls) << b.transpose() << " -> " << a.transpose();
    ASSERT_EQ(back.insideMetres, grid.insideMetres) << b.transpose() << " -> " << a.transpose();
}

TEST(Obstacles, TheGridGivesExactlyTheLossOfWalkingEveryBuilding) {
    for (const double cell : {0.0, 3.0, 40.0, 5000.0}) {
        std::mt19937_64 rng(20261126);
        Obstacles o(9, 0.4, cell);
        std::uniform_real_distribution<double> offset(-20, 20);
        for (int i = 0; i < 20; ++i) {
            for (int j = 0; j < 20; ++j) o.add(building(rng, 60.0 * i + offset(rng), 60.0 * j + offset(rng)));
        }
        o.add(square(0, 0, 50, 50));  // walls shared with the next one
        o.add(square(50, 0, 100, 50));
        o.add(square(5000, 5000, 5010, 5010));  // far out: a sparse grid
        o.add(square(300, 300, 300.0001, 300.0001));
        std::uniform_real_distribution<double> coordinate(-100, 1300);
        std::uniform_int_distribution<int> corner(0, 3);
        int crossed = 0;
        for (int k = 0; k < 6000; ++k) {
            Eigen::Vector2d a(coordinate(rng), coordinate(rng));
            Eigen::Vector2d b(coordinate(rng), coordinate(rng));
            if (k % 7 == 0) b.y() = a.y();                                                 // along the grid's rows
            if (k % 11 == 0) b.x() = a.x();                                                // along its columns
            if (k % 13 == 0) a = Eigen::Vector2d(40.0 * corner(rng), 40.0 * corner(rng));  // on cell corners
            if (k % 17 == 0) b = a;                                                        // no length
            ASSERT_NO_FATAL_FAILURE(expectSame(o, a, b));
            crossed += o.crossingEveryBuilding(a, b).walls > 0;
        }
        // Stopped at some walls: exact below them, at least that many walls from them on.
        for (int k = 0; k < 500; ++k) {
            const Eigen::Vector2d a(coordinate(rng), coordinate(rng));
            const Eigen::Vector2d b(coordinate(rng), coordinate(rng));
            const Obstacles::Crossing every = o.crossingEveryBuilding(a, b);
            const int stop = 1 + k % 8;
            const Obstacles::Crossing stopped = o.crossing(a, b, stop);
            if (every.walls < stop) {
                ASSERT_EQ(stopped.walls, every.walls);
                ASSERT_EQ(stopped.insideMetres, every.insideMetres);
            } else {
                ASSERT_GE(stopped.walls, stop);
                ASSERT_LE(stopped.walls, every.walls);
            }
        }
        ASSERT_NO_FATAL_FAILURE(expectSame(o, {-100, 25}, {6000, 25}));  // along the shared walls' row
        ASSERT_NO_FATAL_FAILURE(expectSame(o, {50, -10}, {50, 60}));     // along a shared wall
        ASSERT_NO_FATAL_FAILURE(expectSame(o, {0, 0}, {5005, 5005}));    // to the far one
        // The segments do cross buildings (most of them several): the comparison is not vacuous.
        EXPECT_GT(crossed, 4500) << "cell " << cell;
        EXPECT_EQ(o.linksEvaluated(), 2 * 6003u + 500);
    }
}

TEST(Obstacles, TheGridCellFollowsTheBuildingsUnlessGiven) {
    Obstacles chosen(9, 0.4);
    for (int i = 0; i < 10; ++i) chosen.add(square(30.0 * i, 0, 30.0 * i + 20, 20));
    EXPECT_DOUBLE_EQ(chosen.gridCellMetres(), 2 * (20 + 2e-3));  // twice the median side
    Obstacles given(9, 0.4, 12.5);
    given.add(square(0, 0, 20, 20));
    EXPECT_EQ(given.gridCellMetres(), 12.5);
    EXPECT_THROW(Obstacles(9, 0.4, -1), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::radio
