#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "ThrownMessage.h"
#include "sbsim/storyboard/geometry/Footprint.h"
#include "sbsim/storyboard/geometry/MovingFootprint.h"
#include "sbsim/storyboard/geometry/PathCurvature.h"
#include "sbsim/storyboard/geometry/Polygon.h"

namespace sbsim::storyboard::geometry {
namespace {

using V = Eigen::Vector2d;

Polygon square() { return Polygon({V(0, 0), V(10, 0), V(10, 10), V(0, 10)}); }

TEST(Polygon, RejectsFewerThanThreeVertices) {
    EXPECT_THROW(Polygon({}), std::invalid_argument);
    EXPECT_THROW(Polygon({V(0, 0), V(1, 0)}), std::invalid_argument);
    EXPECT_EQ(testing_support::thrownMessage([] {
                  Polygon({V(0, 0), V(1, 0)});
              }),
              "a polygon needs at least 3 vertices, got 2");
    EXPECT_NO_THROW(Polygon({V(0, 0), V(1, 0), V(0, 1)}));
    EXPECT_THROW(Polygon({V(0, 0), V(1, NAN), V(0, 1)}), std::invalid_argument);
}

TEST(Polygon, InsideAndOutside) {
    const Polygon p = square();
    EXPECT_TRUE(p.contains(V(5, 5)));
    EXPECT_TRUE(p.contains(V(0.001, 9.999)));
    EXPECT_FALSE(p.contains(V(-1, 5)));
    EXPECT_FALSE(p.contains(V(5, 11)));
    EXPECT_FALSE(p.contains(V(20, 20)));
}

TEST(Polygon, BoundaryIsOutside) {
    const Polygon p = square();
    for (const V& v : {V(0, 5), V(10, 5), V(5, 0), V(5, 10), V(0, 0), V(10, 10), V(10, 0), V(0, 10)}) {
        EXPECT_FALSE(p.contains(v)) << v.transpose();
    }
    // A diamond: its edges are inside its bounding box, and points on them are still outside.
    const Polygon diamond({V(0, -10), V(10, 0), V(0, 10), V(-10, 0)});
    for (const V& v : {V(-5, 5), V(5, 5), V(5, -5), V(-5, -5), V(-2.5, 7.5), V(0, 10), V(-10, 0)}) {
        EXPECT_FALSE(diamond.contains(v)) << v.transpose();
    }
    EXPECT_TRUE(diamond.contains(V(-4.9, 5)));
    EXPECT_FALSE(diamond.contains(V(-5.1, 5)));
    // A slanted edge, with a point exactly on it.
    const Polygon t({V(0, 0), V(3, 1), V(0, 4)});
    EXPECT_FALSE(t.contains(V(1.5, 0.5)));
    EXPECT_TRUE(t.contains(V(1.5, 0.6)));
    EXPECT_FALSE(t.contains(V(1.5, 0.4)));
}

TEST(Polygon, ABoxRingIsAnsweredByItsBoxExactlyAsTheGeneralRule) {
    // A box ring (any start, either direction, closed or not) takes the box shortcut; the same box
    // with an extra vertex on an edge takes the general rule. Both must agree everywhere: inside,
    // outside, on edges and corners, NaN.
    const double x0 = 312.25, x1 = 1200.0, y0 = -7.5, y1 = 400.125;
    const std::vector<V> corners{V(x0, y0), V(x1, y0), V(x1, y1), V(x0, y1)};
    std::vector<V> points;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> ux(x0 - 50, x1 + 50);
    std::uniform_real_distribution<double> uy(y0 - 50, y1 + 50);
    for (int k = 0; k < 2000; ++k) points.emplace_back(ux(rng), uy(rng));
    for (int k = 0; k < 200; ++k) {
        points.emplace_back(x0, uy(rng));  // on the edges and beyond their ends
        points.emplace_back(x1, uy(rng));
        points.emplace_back(ux(rng), y0);
        points.emplace_back(ux(rng), y1);
    }
    for (const V& c : corners) points.push_back(c);
    points.emplace_back(std::nextafter(x0, 1e9), std::nextafter(y0, 1e9));
    points.emplace_back(std::nextafter(x1, 0.0), std::nextafter(y1, 0.0));
    points.emplace_back(NAN, 100);
    points.emplace_back(500, NAN);
    const Polygon general({V(x0, y0), V(700, y0), V(x1, y0), V(x1, y1), V(x0, y1)});
    EXPECT_FALSE(general.isBox());
    std::size_t inside = 0;
    for (const bool reverse : {false, true}) {
        for (std::size_t start = 0; start < 4; ++start) {
            for (const bool closed : {false, true}) {
                std::vector<V> ring;
                for (std::size_t k = 0; k < 4; ++k) ring.push_back(corners[(reverse ? start + 4 - k : start + k) % 4]);
                if (closed) ring.push_back(ring.front());
                const Polygon box(ring);
                ASSERT_TRUE(box.isBox()) << reverse << start << closed;
                for (const V& p : points) {
                    ASSERT_EQ(box.contains(p), general.contains(p)) << p.transpose();
                    inside += box.contains(p);
                }
            }
        }
    }
    EXPECT_GT(inside, 1000u);
    // Not boxes: crossing itself, going round twice, a corner missing, a box too thin.
    EXPECT_FALSE(Polygon({corners[0], corners[2], corners[1], corners[3]}).isBox());
    EXPECT_FALSE(
        Polygon({corners[0], corners[1], corners[2], corners[3], corners[0], corners[1], corners[2], corners[3]})
            .isBox());
    EXPECT_FALSE(Polygon({corners[0], corners[1], corners[2], corners[1]}).isBox());
    EXPECT_FALSE(Polygon({V(0, 0), V(1e-200, 0), V(1e-200, 1), V(0, 1)}).isBox());
    // The bow tie's own rule differs from its box's: the shortcut would have been wrong.
    const Polygon bowTie({corners[0], corners[1], corners[3], corners[2]});
    EXPECT_FALSE(bowTie.isBox());
    EXPECT_FALSE(bowTie.contains(V(x0 + 1, 0.5 * (y0 + y1))));
}

TEST(Polygon, OrientationDoesNotMatter) {
    const Polygon ccw({V(0, 0), V(10, 0), V(10, 10), V(0, 10)});
    const Polygon cw({V(0, 10), V(10, 10), V(10, 0), V(0, 0)});
    for (double x = -1; x <= 11; x += 0.5) {
        for (double y = -1; y <= 11; y += 0.5) {
            EXPECT_EQ(ccw.contains(V(x, y)), cw.contains(V(x, y))) << x << ", " << y;
            EXPECT_EQ(ccw.contains(V(x, y)), x > 0 && x < 10 && y > 0 && y < 10) << x << ", " << y;
        }
    }
}

TEST(Polygon, NonConvex) {
    // A U: the notch between the arms is outside.
    const Polygon u({V(0, 0), V(30, 0), V(30, 30), V(20, 30), V(20, 10), V(10, 10), V(10, 30), V(0, 30)});
    EXPECT_TRUE(u.contains(V(5, 25)));
    EXPECT_TRUE(u.contains(V(25, 25)));
    EXPECT_TRUE(u.contains(V(15, 5)));
    EXPECT_FALSE(u.contains(V(15, 20)));
    EXPECT_FALSE(u.contains(V(15, 10)));  // on the notch's floor
    EXPECT_FALSE(u.contains(V(20, 20)));  // on an inner edge
    // The ray from (5, 10) runs along the notch's floor and through vertices.
    EXPECT_TRUE(u.contains(V(5, 10)));
    EXPECT_TRUE(u.contains(V(25, 10)));
    EXPECT_TRUE(u.contains(V(5, 30 - 1e-9)));
}

TEST(Polygon, RepeatedClosingVertexIsHarmless) {
    const Polygon closed({V(0, 0), V(10, 0), V(10, 10), V(0, 10), V(0, 0)});
    EXPECT_TRUE(closed.contains(V(5, 5)));
    EXPECT_FALSE(closed.contains(V(0, 5)));
    EXPECT_FALSE(closed.contains(V(0, 0)));
}

TEST(Footprint, HeadingFollowsSumoAngles) {
    EXPECT_EQ(Footprint::headingOf(0), V(0, 1));
    EXPECT_EQ(Footprint::headingOf(90), V(1, 0));
    EXPECT_EQ(Footprint::headingOf(180), V(0, -1));
    EXPECT_EQ(Footprint::headingOf(270), V(-1, 0));
    EXPECT_EQ(Footprint::headingOf(-90), V(-1, 0));
    EXPECT_EQ(Footprint::headingOf(450), V(1, 0));
    const V h = Footprint::headingOf(45);
    EXPECT_NEAR(h.x(), std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(h.y(), std::sqrt(0.5), 1e-15);
}

TEST(Footprint, PositionIsTheFrontBumper) {
    const Footprint north = Footprint::fromSumo(V(0, 0), 0, 5, 2);
    EXPECT_EQ(north.centre(), V(0, -2.5));
    EXPECT_EQ(north.frontBumper(), V(0, 0));
    const auto c = north.corners();
    EXPECT_EQ(c[0], V(-1, 0));   // front left
    EXPECT_EQ(c[1], V(1, 0));    // front right
    EXPECT_EQ(c[2], V(1, -5));   // rear right
    EXPECT_EQ(c[3], V(-1, -5));  // rear left

    const Footprint east = Footprint::fromSumo(V(10, 3), 90, 4, 2);
    EXPECT_EQ(east.centre(), V(8, 3));
    EXPECT_EQ(east.corners()[1], V(10, 2));  // front right is to the south
}

TEST(Footprint, MovesAlongTheHeading) {
    const Footprint f = Footprint::fromSumo(V(0, 0), 90, 5, 2);
    EXPECT_EQ(f.moved(10).centre(), V(7.5, 0));
    EXPECT_EQ(f.movedFor(4, 2.5).frontBumper(), V(10, 0));
    EXPECT_EQ(f.moved(-2).frontBumper(), V(-2, 0));
}

TEST(Footprint, TurnsAlongTheCircle) {
    constexpr double kPi = std::numbers::pi;
    constexpr double kEps = 1e-12;
    // Centre (50, 0) heading north, turning left on a circle of radius 50 around the origin: a
    // quarter of it ends at (0, 50) heading west.
    const Footprint f(V(50, 0), V(0, 1), 5, 2);
    const Footprint quarter = f.turned(25 * kPi, 1.0 / 50);
    EXPECT_NEAR(quarter.centre().x(), 0, kEps);
    EXPECT_NEAR(quarter.centre().y(), 50, kEps);
    EXPECT_NEAR(quarter.heading().x(), -1, kEps);
    EXPECT_NEAR(quarter.heading().y(), 0, kEps);
    EXPECT_EQ(quarter.halfLength(), 2.5);
    EXPECT_EQ(quarter.halfWidth(), 1);
    // Turning right (negative curvature) half round the circle about (100, 0): (150, 0), south.
    const Footprint right = f.turned(50 * kPi, -1.0 / 50);
    EXPECT_NEAR(right.centre().x(), 150, kEps);
    EXPECT_NEAR(right.centre().y(), 0, kEps);
    EXPECT_NEAR(right.heading().y(), -1, kEps);
    // Any pose and arc: the centre is the start rotated about the circle's midpoint by κs and
    // stays at radius 1/|κ|; the heading is the tangent there.
    const V heading = Footprint::headingOf(-31);
    const Footprint g(V(3, -7), heading, 4.5, 1.8);
    for (const double curvature : {1.0 / 12, -1.0 / 80, 1.0 / 2400}) {
        const V mid = g.centre() + (1 / curvature) * V(-heading.y(), heading.x());
        for (const double s : {0.5, 7.0, 40.0}) {
            const double a = curvature * s;
            const V r = g.centre() - mid;
            const V expected =
                mid + V(std::cos(a) * r.x() - std::sin(a) * r.y(), std::sin(a) * r.x() + std::cos(a) * r.y());
            const Footprint t = g.turned(s, curvature);
            EXPECT_NEAR((t.centre() - expected).norm(), 0, 1e-9) << curvature << " " << s;
            EXPECT_NEAR((t.centre() - mid).norm(), std::abs(1 / curvature), 1e-9);
            EXPECT_NEAR(t.heading().dot(t.centre() - mid), 0, 1e-9);
            EXPECT_NEAR(t.heading().norm(), 1, 1e-15);
            const V rotated(std::cos(a) * heading.x() - std::sin(a) * heading.y(),
                            std::sin(a) * heading.x() + std::cos(a) * heading.y());
            EXPECT_NEAR((t.heading() - rotated).norm(), 0, 1e-15);
        }
    }
    // A moving footprint with a curvature turns at its speed; without one it drives straight.
    const MovingFootprint onBend(f, 10, 1.0 / 50);
    EXPECT_NEAR((onBend.at(2.5 * kPi).centre() - V(0, 50)).norm(), 0, kEps);
    const MovingFootprint straight(f, 10);
    EXPECT_EQ(straight.at(3).centre(), f.movedFor(10, 3).centre());
}

TEST(Footprint, TheCentreAloneIsTheTurnedFootprintsCentreBitForBit) {
    // The TTC bend test compares centres first with turnedCentre()/centreAt(); they must be the
    // very doubles turned()/at() give, or a pair at the holding circles' edge could change answer.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coordinate(-5000, 5000);
    std::uniform_real_distribution<double> angle(0, 360);
    std::uniform_real_distribution<double> curvature(-0.2, 0.2);
    std::uniform_real_distribution<double> speed(-5, 40);
    std::uniform_real_distribution<double> seconds(0, 30);
    for (int k = 0; k < 20000; ++k) {
        const Footprint f = Footprint::fromSumo(V(coordinate(rng), coordinate(rng)), angle(rng), 5, 1.8);
        const double c = k % 7 == 0 ? 1e-9 : curvature(rng);
        const double v = speed(rng);
        const double t = seconds(rng);
        const V centre = f.turned(v * t, c).centre();
        const V alone = f.turnedCentre(v * t, c);
        ASSERT_EQ(alone.x(), centre.x()) << k;
        ASSERT_EQ(alone.y(), centre.y()) << k;
        for (const double bend : {0.0, c}) {
            const MovingFootprint m(f, v, bend);
            const V at = m.at(t).centre();
            ASSERT_EQ(m.centreAt(t).x(), at.x()) << k;
            ASSERT_EQ(m.centreAt(t).y(), at.y()) << k;
        }
    }
}

TEST(PathCurvature, HeadingChangeWrapsIntoMinusPiToPi) {
    constexpr double kDeg = std::numbers::pi / 180;
    // SUMO angles run clockwise: 350° -> 10° turns right (negative), 10° -> 350° left.
    EXPECT_NEAR(PathCurvature::headingChange(350, 10), -20 * kDeg, 1e-15);
    EXPECT_NEAR(PathCurvature::headingChange(10, 350), 20 * kDeg, 1e-15);
    EXPECT_NEAR(PathCurvature::headingChange(-5, 365), -10 * kDeg, 1e-15);
    EXPECT_EQ(PathCurvature::headingChange(90, 90), 0);
    EXPECT_EQ(PathCurvature::headingChange(0, 360), 0);
    // A half turn is +pi either way: the interval is open at -pi.
    EXPECT_EQ(PathCurvature::headingChange(0, 180), std::numbers::pi);
    EXPECT_EQ(PathCurvature::headingChange(180, 0), std::numbers::pi);
    EXPECT_EQ(PathCurvature::headingChange(90, 270), std::numbers::pi);
    // Just past a half turn clockwise is just short of one counter-clockwise, and the other way.
    EXPECT_NEAR(PathCurvature::headingChange(0, 180.000001), std::numbers::pi - 1e-6 * kDeg, 1e-12);
    EXPECT_NEAR(PathCurvature::headingChange(0, 179.999999), -std::numbers::pi + 1e-6 * kDeg, 1e-12);
}

TEST(PathCurvature, HeadingChangeOverDistance) {
    constexpr double kDeg = std::numbers::pi / 180;
    // 10 m north, heading 0° -> 355°: 5° left over 10 m.
    EXPECT_NEAR(PathCurvature::of(V(0, 0), 0, V(0, 10), 355, 10), 5 * kDeg / 10, 1e-15);
    EXPECT_NEAR(PathCurvature::of(V(0, 0), 355, V(0, 10), 5, 10), -10 * kDeg / 10, 1e-15);
    // The distance is the straight one between the two front bumpers.
    EXPECT_NEAR(PathCurvature::of(V(1, 1), 90, V(4, 5), 80, 3), 10 * kDeg / 5, 1e-15);
}

TEST(PathCurvature, ThresholdsMeanStraight) {
    const double bend = PathCurvature::of(V(0, 0), 0, V(0, 10), 355, 1);
    EXPECT_GT(bend, 0);
    EXPECT_EQ(PathCurvature::of(V(0, 0), 0, V(0, 10), 355, 0.999), 0);  // too slow
    EXPECT_EQ(PathCurvature::of(V(0, 0), 0, V(0, 10), 355, 0), 0);
    EXPECT_GT(PathCurvature::of(V(0, 0), 0, V(0, 0.01), 355, 5), 0);  // the shortest distance
    EXPECT_EQ(PathCurvature::of(V(0, 0), 0, V(0, 0.0099), 355, 5), 0);
    EXPECT_EQ(PathCurvature::of(V(0, 0), 0, V(0, 0), 355, 5), 0);
    // A radius of 2500 m curves; 2600 m counts as straight.
    const double degreesOver100m = [](double radius) { return 100 / radius * 180 / std::numbers::pi; }(2499);
    EXPECT_GT(PathCurvature::of(V(0, 0), 0, V(0, 100), 360 - degreesOver100m, 10), 0);
    const double gentle = 100 / 2600.0 * 180 / std::numbers::pi;
    EXPECT_EQ(PathCurvature::of(V(0, 0), 0, V(0, 100), 360 - gentle, 10), 0);
    EXPECT_EQ(PathCurvature::of(V(0, 0), 360 - gentle, V(0, 100), 0, 10), 0);
    EXPECT_EQ(PathCurvature::of(V(0, 0), 0, V(0, 100), 0, 10), 0);
    EXPECT_EQ(PathCurvature::of(V(0, 0), 0, V(0, 100), 0, std::nan("")), 0);
}

TEST(Footprint, OverlapAndSeparation) {
    const Footprint a = Footprint::fromSumo(V(0, 0), 0, 5, 2);
    EXPECT_TRUE(overlaps(a, a));
    EXPECT_TRUE(overlaps(a, Footprint::fromSumo(V(0.5, 1), 0, 5, 2)));
    EXPECT_FALSE(overlaps(a, Footprint::fromSumo(V(0, 5.1), 0, 5, 2)));  // 0.1 m ahead
    EXPECT_FALSE(overlaps(a, Footprint::fromSumo(V(2.1, 0), 0, 5, 2)));  // 0.1 m beside
    // Perpendicular: a car crossing just in front.
    EXPECT_FALSE(overlaps(a, Footprint::fromSumo(V(3, 1.01), 90, 5, 2)));
    EXPECT_TRUE(overlaps(a, Footprint::fromSumo(V(3, 0.99), 90, 5, 2)));
}

TEST(Footprint, TouchingOverlaps) {
    const Footprint a = Footprint::fromSumo(V(0, 0), 0, 5, 2);
    EXPECT_TRUE(overlaps(a, Footprint::fromSumo(V(0, 5), 0, 5, 2)));    // nose to tail
    EXPECT_TRUE(overlaps(a, Footprint::fromSumo(V(2, 0), 0, 5, 2)));    // side by side
    EXPECT_TRUE(overlaps(a, Footprint::fromSumo(V(2, 5), 0, 5, 2)));    // corner to corner
    EXPECT_TRUE(overlaps(a, Footprint::fromSumo(V(0, 0), 180, 5, 2)));  // nose to nose
    EXPECT_FALSE(overlaps(a, Footprint::fromSumo(V(0, 0.001), 180, 5, 2)));
    // Touching along a slanted edge: b's rear edge lies on a's front-right edge line.
    const Footprint r = Footprint::fromSumo(V(0, 0), 30, 4, 2);
    const Footprint beside = Footprint(r.centre() + 2 * r.right(), r.heading(), 4, 2);
    EXPECT_TRUE(overlaps(r, beside));
    EXPECT_FALSE(overlaps(r, Footprint(r.centre() + 2.001 * r.right(), r.heading(), 4, 2)));
}

TEST(Footprint, OnlyTheOtherRectanglesAxisSeparates) {
    // a's axes see overlapping projections; b's diagonal axis separates them.
    const Footprint a(V(0, 0), V(0, 1), 2, 2);
    const Footprint far(V(1.9, 1.9), Footprint::headingOf(45), 2, 2);
    EXPECT_FALSE(overlaps(a, far));
    EXPECT_FALSE(overlaps(far, a));
    const Footprint near(V(1.6, 1.6), Footprint::headingOf(45), 2, 2);
    EXPECT_TRUE(overlaps(a, near));
    EXPECT_TRUE(overlaps(near, a));
}

}  // namespace
}  // namespace sbsim::storyboard::geometry
