#include "sbsim/storyboard/conditions/TtcCondition.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

#include "StoryboardTestSupport.h"
#include "ThrownMessage.h"
#include "sbsim/storyboard/geometry/PathCurvature.h"

namespace sbsim::storyboard::test {
namespace {

using geometry::Footprint;
using geometry::MovingFootprint;
using V = Eigen::Vector2d;

/// The definition: every sample time i·dt, i = 1..ceil(ttc/dt).
bool naiveConflict(const Footprint& a, double va, const Footprint& b, double vb, double ttc) {
    if (va == 0 && vb == 0) return false;
    double dt = std::numeric_limits<double>::infinity();
    if (va != 0) dt = 2 * a.halfLength() / std::abs(va);
    if (vb != 0) dt = std::min(dt, 2 * b.halfLength() / std::abs(vb));
    const auto steps = static_cast<long>(std::ceil(ttc / dt));
    for (long i = 1; i <= steps; ++i) {
        const double t = static_cast<double>(i) * dt;
        if (overlaps(a.movedFor(va, t), b.movedFor(vb, t))) return true;
    }
    return false;
}

/// The definition for movers that may be on a bend: every sample, each footprint where at() puts it.
bool naiveConflict(const MovingFootprint& a, const MovingFootprint& b, double ttc) {
    if (a.speed == 0 && b.speed == 0) return false;
    const double dt = std::min(a.circle.sampleStep, b.circle.sampleStep);
    const auto steps = static_cast<long>(std::ceil(ttc / dt));
    for (long i = 1; i <= steps; ++i) {
        const double t = static_cast<double>(i) * dt;
        if (overlaps(a.at(t), b.at(t))) return true;
    }
    return false;
}

/// A car driving counter-clockwise on the ring of radius `r` around the origin, its front bumper
/// at polar angle `phi` (radians).
Vehicle ringCar(std::string id, double r, double phi, double speed) {
    return car(std::move(id), r * std::cos(phi), r * std::sin(phi), speed, -phi * 180 / std::numbers::pi);
}

TEST(TtcCondition, HeadOn) {
    // Fronts 40 m apart, closing at 20 m/s: they touch at t = 2 s.
    Scene scene({car("north", 0, 0, 10, 0), car("south", 0, 40, 10, 180)});
    TtcCondition soon(3);
    EXPECT_EQ(scene.others(scene.test(soon, "north")), (Ids{"south"}));
    EXPECT_EQ(scene.others(scene.test(soon, "south")), (Ids{"north"}));
    TtcCondition exactly(2);  // touching at the last sample counts
    EXPECT_EQ(scene.others(scene.test(exactly, "north")), (Ids{"south"}));
    TtcCondition tooShort(1.5);
    const ConditionResult r = scene.test(tooShort, "north");
    EXPECT_TRUE(r.isSet());
    EXPECT_FALSE(r.isTrue());
}

TEST(TtcCondition, RearEnd) {
    // The leader's rear is 25 m ahead; the follower closes at 10 m/s, touching at t = 2.5 s.
    // dt = min(5/20, 5/10) = 0.25 s.
    Scene scene({car("follower", 0, 0, 20, 0), car("leader", 0, 30, 10, 0)});
    TtcCondition enough(2.5);
    EXPECT_EQ(scene.others(scene.test(enough, "follower")), (Ids{"leader"}));
    EXPECT_EQ(scene.others(scene.test(enough, "leader")), (Ids{"follower"}));
    TtcCondition justShort(2.2);  // samples up to 2.25 s
    EXPECT_FALSE(scene.test(justShort, "follower"));
    TtcCondition roundedUp(2.4);  // ceil(2.4 / 0.25) = 10 samples reach 2.5 s
    EXPECT_TRUE(scene.test(roundedUp, "follower"));
}

TEST(TtcCondition, SameSpeedFollowingNeverConflicts) {
    Scene scene({car("a", 0, 0, 20, 0), car("b", 0, 5.5, 20, 0)});
    TtcCondition c(30);
    EXPECT_FALSE(scene.test(c, "a"));
    EXPECT_FALSE(scene.test(c, "b"));
}

TEST(TtcCondition, Crossing) {
    // Both fronts reach the crossing point (0, 0) at t = 2 s.
    Scene scene({car("east", -20, 0, 10, 90), car("northbound", 0, -20, 10, 0)});
    TtcCondition c(3);
    EXPECT_EQ(scene.others(scene.test(c, "east")), (Ids{"northbound"}));
    EXPECT_EQ(scene.others(scene.test(c, "northbound")), (Ids{"east"}));
    TtcCondition tooShort(1);
    EXPECT_FALSE(scene.test(tooShort, "east"));
    // The crossing car passes well before: it is 40 m further ahead.
    Scene passed({car("east", -20, 0, 10, 90), car("northbound", 0, 20, 10, 0)});
    EXPECT_FALSE(passed.test(c, "east"));
}

TEST(TtcCondition, ParallelLanesDoNotConflict) {
    // Overtaking in the next lane (3.2 m apart, 1.8 m wide cars): no overlap ever.
    Scene scene({car("fast", 0, 0, 30, 0), car("slow", 3.2, 10, 10, 0), car("oncoming", -3.2, 60, 15, 180)});
    TtcCondition c(10);
    EXPECT_FALSE(scene.test(c, "fast"));
    EXPECT_FALSE(scene.test(c, "slow"));
    EXPECT_FALSE(scene.test(c, "oncoming"));
}

TEST(TtcCondition, TouchingCountsAsOverlap) {
    // Side by side, exactly one width apart, same speed: touching at every sample.
    Scene scene({car("left", 0, 0, 10, 0), car("right", 1.8, 0, 10, 0), car("gap", 5.6001, 0, 10, 0)});
    TtcCondition c(1);
    EXPECT_EQ(scene.others(scene.test(c, "left")), (Ids{"right"}));
    EXPECT_EQ(scene.others(scene.test(c, "right")), (Ids{"left"}));
    EXPECT_FALSE(scene.test(c, "gap"));
}

TEST(TtcCondition, StandingVehicles) {
    // Two standing vehicles never conflict, even overlapping.
    Scene standing({car("a", 0, 0, 0, 0), car("b", 0, 1, 0, 0)});
    TtcCondition c(5);
    EXPECT_FALSE(standing.test(c, "a"));
    // A moving car runs into a standing one; dt comes from the moving car alone (5 m / 10 m/s).
    Scene obstacle({car("mover", 0, 0, 10, 0), car("parked", 0, 25, 0, 0), car("parkedAside", 3, 25, 0, 0)});
    EXPECT_EQ(obstacle.others(obstacle.test(c, "mover")), (Ids{"parked"}));
    EXPECT_EQ(obstacle.others(obstacle.test(c, "parked")), (Ids{"mover"}));
    // A standing car across the path.
    Scene crossingObstacle({car("mover", -20, 0, 10, 90), car("blocking", 0, 2.5, 0, 0)});
    EXPECT_TRUE(crossingObstacle.test(c, "mover"));
}

TEST(TtcCondition, DistanceIsInclusivePositionToPosition) {
    // Head-on, fronts exactly 40 m apart.
    Scene scene({car("north", 0, 0, 10, 0), car("south", 0, 40, 10, 180)});
    TtcCondition within(3, 40);
    EXPECT_EQ(within.neighbourRadius(), 40.0);
    EXPECT_TRUE(scene.test(within, "north"));
    TtcCondition outside(3, 39.999);
    EXPECT_FALSE(scene.test(outside, "north"));
    TtcCondition defaultDistance(3);
    EXPECT_EQ(defaultDistance.distance(), 100.0);
}

TEST(TtcCondition, RejectsBadParameters) {
    EXPECT_THROW(TtcCondition(0), std::invalid_argument);
    EXPECT_THROW(TtcCondition(-1), std::invalid_argument);
    EXPECT_THROW(TtcCondition(std::nan("")), std::invalid_argument);
    EXPECT_THROW(TtcCondition(1, -5), std::invalid_argument);
    EXPECT_THROW(TtcCondition(1, std::numeric_limits<double>::infinity()), std::invalid_argument);
    EXPECT_EQ(testing_support::thrownMessage([] { TtcCondition(-1.5); }),
              "TtcCondition: ttc must be finite and > 0, not -1.500000");
    EXPECT_EQ(testing_support::thrownMessage([] { TtcCondition(1, -5); }),
              "TtcCondition: distance must be finite and >= 0, not -5.000000");
}

TEST(TtcCondition, ConflictEqualsSamplingEveryStep) {
    std::mt19937_64 rng(4242);
    std::uniform_real_distribution<double> unit(0, 1);
    int conflicts = 0;
    int touchingCases = 0;
    constexpr int kPairs = 40'000;
    for (int k = 0; k < kPairs; ++k) {
        const auto angle = [&] { return unit(rng) < 0.5 ? 90.0 * std::floor(unit(rng) * 4) : 360 * unit(rng); };
        const auto speed = [&] { return unit(rng) < 0.2 ? 0.0 : std::round(40 * unit(rng) * 4) / 4; };
        const Footprint a = Footprint::fromSumo(V(0, 0), angle(), 3 + std::round(9 * unit(rng)), 1.5 + unit(rng));
        Footprint b = Footprint::fromSumo(V(120 * unit(rng) - 60, 120 * unit(rng) - 60), angle(),
                                          3 + std::round(9 * unit(rng)), 1.5 + unit(rng));
        if (k % 4 == 0) {
            // Parallel and exactly touching sideways: the delicate case for the interval search.
            b = Footprint(a.centre() + (a.halfWidth() + b.halfWidth()) * a.right() + 20 * unit(rng) * a.heading(),
                          a.heading(), 2 * b.halfLength(), 2 * b.halfWidth());
            ++touchingCases;
        }
        const double va = speed();
        const double vb = speed();
        const double ttc = std::vector<double>{0.3, 1, 2.5, 6, 12}[k % 5];
        const bool expected = naiveConflict(a, va, b, vb, ttc);
        ASSERT_EQ(TtcCondition::conflict(a, va, b, vb, ttc), expected)
            << "pair " << k << ": a " << a.centre().transpose() << " h " << a.heading().transpose() << " v " << va
            << "; b " << b.centre().transpose() << " h " << b.heading().transpose() << " v " << vb << "; ttc " << ttc;
        // prepare() tests each pair once for both vehicles: exact only if swapping them gives the
        // same answer, bit for bit.
        ASSERT_EQ(TtcCondition::conflict(b, vb, a, va, ttc), expected) << "swapped pair " << k;
        conflicts += expected;
    }
    EXPECT_GT(touchingCases, 0);
    EXPECT_GT(conflicts, kPairs / 20);  // both outcomes are well represented
    EXPECT_LT(conflicts, kPairs * 19 / 20);
}

TEST(TtcCondition, MatchesAllPairsOnRandomTraffic) {
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> coordinate(0, 250);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Vehicle> vehicles;
    for (int k = 0; k < 400; ++k) {
        vehicles.push_back(car("v" + std::to_string(k), coordinate(rng), coordinate(rng),
                               unit(rng) < 0.2 ? 0 : 30 * unit(rng), 360 * unit(rng), 4 + 3 * unit(rng),
                               1.6 + 0.8 * unit(rng)));
    }
    Scene scene(vehicles, SimTime::fromSeconds(3), 40);
    const traffic::VehicleSnapshot& s = scene.snapshot();
    TtcCondition c(4, 40);
    c.prepare(scene.ctx());
    std::size_t total = 0;
    for (VehicleIndex ego = 0; ego < s.size(); ++ego) {
        std::vector<VehicleIndex> expected;
        const Footprint fe =
            Footprint::fromSumo(s.positions().col(ego), s.angles()[ego], s.lengths()[ego], s.widths()[ego]);
        for (VehicleIndex o = 0; o < s.size(); ++o) {
            if (o == ego || (s.positions().col(o) - s.positions().col(ego)).squaredNorm() > 40.0 * 40.0) continue;
            const Footprint fo =
                Footprint::fromSumo(s.positions().col(o), s.angles()[o], s.lengths()[o], s.widths()[o]);
            if (naiveConflict(fe, s.speeds()[ego], fo, s.speeds()[o], 4)) expected.push_back(o);
        }
        ASSERT_EQ(c.test(scene.ctx(), ego).others(), expected) << "ego " << ego;
        total += expected.size();
    }
    EXPECT_GT(total, 20u);
}

TEST(TtcCondition, CurvedConflictEqualsSamplingEveryStep) {
    std::mt19937_64 rng(5150);
    std::uniform_real_distribution<double> unit(0, 1);
    int conflicts = 0;
    constexpr int kPairs = 20'000;
    for (int k = 0; k < kPairs; ++k) {
        const auto speed = [&] { return unit(rng) < 0.15 ? 0.0 : std::round(30 * unit(rng) * 4) / 4; };
        // Radii from 5 m to 500 m either way, or straight.
        const auto curvature = [&] {
            const double c = unit(rng) < 0.25 ? 0.0 : 1 / (5 + 495 * unit(rng) * unit(rng));
            return unit(rng) < 0.5 ? c : -c;
        };
        const MovingFootprint a(Footprint::fromSumo(V(0, 0), 360 * unit(rng), 3 + std::round(9 * unit(rng)), 1.8),
                                speed(), curvature());
        const MovingFootprint b(Footprint::fromSumo(V(50 * unit(rng) - 25, 50 * unit(rng) - 25), 360 * unit(rng),
                                                    3 + std::round(9 * unit(rng)), 1.8),
                                speed(), curvature());
        const double ttc = std::vector<double>{0.5, 2, 4, 8}[k % 4];
        const bool expected = naiveConflict(a, b, ttc);
        ASSERT_EQ(TtcCondition::conflict(a, b, ttc), expected) << "pair " << k;
        ASSERT_EQ(TtcCondition::conflict(b, a, ttc), expected) << "swapped pair " << k;
        conflicts += expected;
    }
    EXPECT_GT(conflicts, kPairs / 20);
    EXPECT_LT(conflicts, kPairs * 19 / 20);
}

TEST(TtcCondition, RingConvergingOnlyWithCurves) {
    // A fast car closes on a slow one on a ring of radius 40 m: 15 m between the follower's front
    // and the leader's rear, closing at 15 m/s. Straight on, the follower leaves the ring along
    // its tangent (5 m off it after 20 m) and misses.
    constexpr double kR = 40;
    const auto step = [&](double t) {
        return std::vector<Vehicle>{ringCar("leader", kR, (5 * t) / kR, 5),
                                    ringCar("follower", kR, (20 * t - 35) / kR, 20)};
    };
    Scene scene(step(0), SimTime::zero());
    TtcCondition c(3, 50);
    EXPECT_FALSE(scene.test(c, "follower"));  // the first step has no bend yet: straight
    scene.set(step(1), SimTime::fromSeconds(1));
    EXPECT_EQ(scene.others(scene.test(c, "follower")), (Ids{"leader"}));
    EXPECT_EQ(scene.others(scene.test(c, "leader")), (Ids{"follower"}));
    // Testing the same step again compares with the same previous step.
    EXPECT_EQ(scene.others(scene.test(c, "follower")), (Ids{"leader"}));
    const double expectedCurvature = 0.125 / (2 * kR * std::sin(0.0625));  // heading change over the chord
    EXPECT_NEAR(c.curvature(scene.index("leader")), expectedCurvature, 1e-12);
    EXPECT_GT(c.curvature(scene.index("follower")), 0.99 / kR);

    TtcCondition straight(3, 50);  // has not seen the step before: straight lines
    EXPECT_FALSE(scene.test(straight, "follower"));
    EXPECT_EQ(straight.curvature(scene.index("follower")), 0);
    // Predicted on the ring, the follower reaches the leader after 1 s (15 m at 15 m/s).
    TtcCondition tooShort(0.7, 50);  // samples up to 0.75 s
    Scene twice(step(0), SimTime::zero());
    (void)twice.test(tooShort, "follower");
    twice.set(step(1), SimTime::fromSeconds(1));
    EXPECT_FALSE(twice.test(tooShort, "follower"));
}

TEST(TtcCondition, StraightDrivingMatchesTheStraightPrediction) {
    // Random traffic that drove straight on between two steps gets exactly the straight-line
    // answer, as a condition without a previous step (the prediction before curves) gives.
    std::mt19937_64 rng(78);
    std::uniform_real_distribution<double> coordinate(0, 250);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Vehicle> before;
    std::vector<Vehicle> after;
    for (int k = 0; k < 400; ++k) {
        Vehicle v = car("v" + std::to_string(k), coordinate(rng), coordinate(rng), unit(rng) < 0.2 ? 0 : 30 * unit(rng),
                        unit(rng) < 0.3 ? 90.0 * std::floor(4 * unit(rng)) : 360 * unit(rng), 4 + 3 * unit(rng),
                        1.6 + 0.8 * unit(rng));
        Vehicle moved = v;
        const V step = 0.5 * v.speed * Footprint::headingOf(v.angle);
        v.x -= step.x();
        v.y -= step.y();
        // Some drift by less than the straight threshold (a 3 km radius).
        if (k % 3 == 0) moved.angle += step.norm() / 3000 * 180 / std::numbers::pi;
        before.push_back(v);
        after.push_back(moved);
    }
    Scene scene(before, SimTime::fromSeconds(2.5), 40);
    TtcCondition c(4, 40);
    c.prepare(scene.ctx());
    scene.set(after, SimTime::fromSeconds(3), 40);
    c.prepare(scene.ctx());
    TtcCondition fresh(4, 40);
    fresh.prepare(scene.ctx());
    std::size_t total = 0;
    for (VehicleIndex ego = 0; ego < scene.snapshot().size(); ++ego) {
        ASSERT_EQ(c.curvature(ego), 0) << ego;
        const ConditionResult r = c.test(scene.ctx(), ego);
        ASSERT_EQ(r.others(), fresh.test(scene.ctx(), ego).others()) << "ego " << ego;
        total += r.others().size();
    }
    EXPECT_GT(total, 20u);
}

TEST(TtcCondition, PairsTestedAheadGiveTheSameAnswers) {
    // With a pool, prepare() tests the pairs ahead once test() asked about most vehicles in the
    // step before; the answers equal testing vehicle by vehicle, on bends as well.
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> coordinate(0, 250);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Vehicle> steps[3];
    for (int k = 0; k < 600; ++k) {
        Vehicle v = car("v" + std::to_string(k), coordinate(rng), coordinate(rng), unit(rng) < 0.2 ? 0 : 30 * unit(rng),
                        360 * unit(rng), 4 + 3 * unit(rng), 1.6 + 0.8 * unit(rng));
        const double turn = unit(rng) < 0.5 ? 0 : 40 * unit(rng) - 20;  // degrees per step
        for (auto& step : steps) {
            step.push_back(v);
            const V ahead = 0.5 * v.speed * Footprint::headingOf(v.angle);
            v.x += ahead.x();
            v.y += ahead.y();
            v.angle += turn;
        }
    }
    kernel::ParallelFor pool(2);
    TtcCondition ahead(3, 40);
    TtcCondition oneByOne(3, 40);
    std::size_t total = 0;
    for (int t = 0; t < 3; ++t) {
        Scene scene(steps[t], SimTime::fromSeconds(0.5 * t), 40);
        const EvaluationContext pooled(scene.snapshot(), scene.grid(), nullptr, &pool);
        ahead.prepare(pooled);
        EXPECT_EQ(ahead.pairsTestedAhead(), t > 0) << "step " << t;  // the first step has no history
        oneByOne.prepare(scene.ctx());
        for (VehicleIndex ego = 0; ego < scene.snapshot().size(); ++ego) {
            const ConditionResult r = ahead.test(pooled, ego);
            ASSERT_EQ(r.others(), oneByOne.test(scene.ctx(), ego).others()) << "step " << t << " ego " << ego;
            total += r.others().size();
        }
    }
    EXPECT_GT(total, 100u);
}

TEST(TtcCondition, KeepsPosesOnlyOfRunningVehicles) {
    Scene scene({ringCar("a", 40, 0, 10), ringCar("b", 40, 1, 10), ringCar("c", 40, 2, 10)}, SimTime::zero());
    TtcCondition c(2);
    c.prepare(scene.ctx());
    EXPECT_EQ(c.heldVehicles(), 3u);
    c.forget("b");
    EXPECT_EQ(c.heldVehicles(), 2u);
    scene.set({ringCar("a", 40, 0.25, 10), ringCar("c", 40, 2.25, 10)}, SimTime::fromSeconds(1));
    c.prepare(scene.ctx());
    EXPECT_EQ(c.heldVehicles(), 2u);
    EXPECT_NE(c.curvature(scene.index("a")), 0);
    // A vehicle that left and came back with the same id starts without a bend.
    c.forget("a");
    scene.set({ringCar("a", 40, 0.5, 10), ringCar("c", 40, 2.5, 10)}, SimTime::fromSeconds(2));
    c.prepare(scene.ctx());
    EXPECT_EQ(c.curvature(scene.index("a")), 0);
    EXPECT_NE(c.curvature(scene.index("c")), 0);
    scene.set({}, SimTime::fromSeconds(3));
    c.prepare(scene.ctx());
    scene.set({}, SimTime::fromSeconds(4));
    c.prepare(scene.ctx());
    EXPECT_EQ(c.heldVehicles(), 0u);
}

TEST(TtcCondition, PosesFollowTheirVehiclesWhetherOrNotOthersCameOrWent) {
    // While the same vehicles run (the snapshot's idsVersion() unchanged) each vehicle's previous
    // pose is at its own index; once one came or went (as many as before, or not) the poses are
    // matched by id. A pose taken from another vehicle would bend a straight driver, or
    // straighten the one on the ring.
    constexpr double kR = 40;
    const auto east = [](std::string id, double t) { return car(std::move(id), 10 * t, 100, 10, 90); };
    const auto north = [](std::string id, double t) { return car(std::move(id), 200, 10 * t, 10, 0); };
    const auto ring = [&](std::string id, double t) { return ringCar(std::move(id), kR, 10 * t / kR, 10); };
    TtcCondition c(2, 50);
    Scene scene({ring("a", 0), east("b", 0), north("c", 0)}, SimTime::zero());
    c.prepare(scene.ctx());
    const auto expectBends = [&](const char* when, std::vector<std::string> straight, std::vector<std::string> bent) {
        for (const std::string& id : straight) EXPECT_EQ(c.curvature(scene.index(id)), 0) << id << " " << when;
        for (const std::string& id : bent) EXPECT_GT(c.curvature(scene.index(id)), 0.99 / kR) << id << " " << when;
    };
    scene.set({ring("a", 1), east("b", 1), north("c", 1)}, SimTime::fromSeconds(1));
    const std::uint64_t version = scene.snapshot().idsVersion();
    c.prepare(scene.ctx());
    expectBends("with the same vehicles", {"b", "c"}, {"a"});
    scene.set({ring("a", 2), east("b", 2), north("c", 2)}, SimTime::fromSeconds(2));
    ASSERT_EQ(scene.snapshot().idsVersion(), version);
    c.prepare(scene.ctx());
    expectBends("with the same vehicles again", {"b", "c"}, {"a"});
    // c left and "0" came: as many vehicles, each of a, b one index further.
    c.forget("c");
    scene.set({east("0", 3), ring("a", 3), east("b", 3)}, SimTime::fromSeconds(3));
    ASSERT_NE(scene.snapshot().idsVersion(), version);
    c.prepare(scene.ctx());
    expectBends("after one came and one went", {"0", "b"}, {"a"});
    scene.set({east("0", 4), ring("a", 4), east("b", 4), north("d", 4)}, SimTime::fromSeconds(4));
    c.prepare(scene.ctx());
    expectBends("after one more came", {"0", "b", "d"}, {"a"});
    // "0" missing from this snapshot (not forgotten) and x new: as many as before, a and b one
    // index lower.
    scene.set({ring("a", 5), east("b", 5), north("d", 5), east("x", 5)}, SimTime::fromSeconds(5));
    c.prepare(scene.ctx());
    expectBends("with one missing and one new", {"b", "d", "x"}, {"a"});
}

TEST(TtcCondition, LongHorizonEqualsSamplingEveryStep) {
    // Horizons long enough that the candidate runs pass 2·64 samples, where conflict() tests
    // the ends and the middle only: the answer must be what every sample gives.
    std::mt19937_64 rng(909);
    std::uniform_real_distribution<double> unit(0, 1);
    int conflicts = 0;
    constexpr int kPairs = 3'000;
    for (int k = 0; k < kPairs; ++k) {
        const double angle = 360 * unit(rng);
        const Footprint a = Footprint::fromSumo(V(0, 0), angle, 3 + std::round(9 * unit(rng)), 1.8);
        // Ahead or behind in the same lane or the next, the same heading or nearly: long runs.
        const V offset = (300 * unit(rng) - 150) * a.heading() + (6 * unit(rng) - 3) * a.right();
        const Footprint b = Footprint::fromSumo(a.centre() + offset, angle + (unit(rng) < 0.5 ? 0 : unit(rng) - 0.5),
                                                3 + std::round(9 * unit(rng)), 1.8);
        const double va = 5 + 30 * unit(rng);
        const double vb = unit(rng) < 0.3 ? va : va + 0.2 * unit(rng) - 0.1;
        const double ttc = std::vector<double>{60, 600, 3000}[k % 3];
        const bool expected = naiveConflict(a, va, b, vb, ttc);
        ASSERT_EQ(TtcCondition::conflict(a, va, b, vb, ttc), expected) << "pair " << k << "; ttc " << ttc;
        conflicts += expected;
    }
    EXPECT_GT(conflicts, kPairs / 50);
}

TEST(TtcCondition, HugeHorizonIsBoundedWork) {
    // TtcCondition(1e308): about 1e15 samples per pair before; each call must now end at once.
    const auto start = std::chrono::steady_clock::now();
    const Footprint north = Footprint::fromSumo(V(0, 0), 0, 5, 1.8);
    EXPECT_TRUE(TtcCondition::conflict(north, 10, Footprint::fromSumo(V(0, 400), 180, 5, 1.8), 10, 1e308));
    EXPECT_FALSE(TtcCondition::conflict(north, 10, Footprint::fromSumo(V(0, 6), 0, 5, 1.8), 10, 1e308));
    EXPECT_TRUE(TtcCondition::conflict(north, 10.001, Footprint::fromSumo(V(0, 300), 0, 5, 1.8), 10, 1e308));
    EXPECT_FALSE(TtcCondition::conflict(north, 10, Footprint::fromSumo(V(4, 0), 0, 5, 1.8), 10.001, 1e308));
    // On bends: circles never part, the samples are capped.
    const MovingFootprint left(north, 10, 1 / 50.0);
    const MovingFootprint right(Footprint::fromSumo(V(300, 0), 0, 5, 1.8), 10, -1 / 50.0);
    EXPECT_FALSE(TtcCondition::conflict(left, right, 1e308));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
}

}  // namespace
}  // namespace sbsim::storyboard::test
