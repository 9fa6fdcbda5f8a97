#include "sbsim/storyboard/StepPairs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "StoryboardTestSupport.h"
#include "sbsim/kernel/ParallelFor.h"
#include "sbsim/storyboard/StepNeighbours.h"
#include "sbsim/storyboard/conditions/SpeedDifferenceCondition.h"
#include "sbsim/storyboard/conditions/TtcCondition.h"
#include "sbsim/storyboard/geometry/Footprint.h"

namespace sbsim::storyboard::test {
namespace {

using Pair = StepPairs::Pair;

/// Keeps every pair it is handed (smaller index first) and records what it got after the sweep.
class Recorder : public StepPairs::User {
public:
    explicit Recorder(double radius) : radius_(radius) {}
    double pairRadius() const override { return radius_; }
    void sweepRow(const traffic::VehicleSnapshot& /*snapshot*/, const traffic::PairSweep& sweep, std::size_t row,
                  StepPairs::Handover& handover, std::vector<Pair>& kept) const override {
        sweep.forEachPairInRow(row, [&](VehicleIndex a, VehicleIndex b, double d2) {
            handover.offer(a, b, d2);
            kept.emplace_back(std::min(a, b), std::max(a, b));
        });
        ++swept;
    }
    void keepPairs(const traffic::VehicleSnapshot& /*snapshot*/, std::span<const Pair> pairs,
                   std::vector<Pair>& kept) const override {
        for (const auto& [a, b] : pairs) kept.emplace_back(std::min(a, b), std::max(a, b));
    }
    void pairsKept(const traffic::VehicleSnapshot& /*snapshot*/, const std::vector<Pair>& kept) override {
        got = kept;
        ++runs;
    }
    std::vector<Pair> got;
    int runs = 0;
    mutable std::atomic<int> swept{0};  // rows this user swept itself

private:
    double radius_;
};

/// Every pair (smaller index first, ascending) within `radius` by the definition.
std::vector<Pair> within(const traffic::VehicleSnapshot& s, double radius) {
    std::vector<Pair> out;
    for (VehicleIndex a = 0; a < s.size(); ++a) {
        for (VehicleIndex b = a + 1; b < s.size(); ++b) {
            const double dx = s.positions()(0, b) - s.positions()(0, a);
            const double dy = s.positions()(1, b) - s.positions()(1, a);
            if (dx * dx + dy * dy <= radius * radius) out.emplace_back(a, b);
        }
    }
    return out;
}

/// Random positions and a 10 m lattice (pairs exactly 30 m and 50 m apart: 30-40-50 triangles),
/// a NaN and an infinite position.
std::vector<Vehicle> mixedTraffic(unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> coordinate(-200, 200);
    std::vector<Vehicle> vehicles;
    for (int k = 0; k < 500; ++k) {
        const bool lattice = k % 2 == 0;
        const double x = lattice ? 10.0 * std::round(coordinate(rng) / 10) : coordinate(rng);
        const double y = lattice ? 10.0 * std::round(coordinate(rng) / 10) : coordinate(rng);
        vehicles.push_back(car("v" + std::to_string(k), x, y));
    }
    vehicles.push_back(car("nan", std::numeric_limits<double>::quiet_NaN(), 0));
    vehicles.push_back(car("inf", std::numeric_limits<double>::infinity(), 5));
    return vehicles;
}

TEST(StepPairs, EachUserGetsExactlyThePairsWithinItsOwnRadiusFromOneSweep) {
    const Scene scene(mixedTraffic(99), SimTime::fromSeconds(1));
    kernel::ParallelFor pool(3);
    StepPairs pairs;
    // Largest first and last, two users of one radius, a radius of 0 (only vehicles at one spot).
    Recorder r50(50), r30(30), r30b(30), r12(12.5), r0(0), r50b(50);
    std::size_t sweeps = 0;
    for (kernel::ParallelFor* parallel : {&pool, static_cast<kernel::ParallelFor*>(nullptr)}) {
        const EvaluationContext ctx(scene.snapshot(), scene.grid(), nullptr, parallel);
        for (Recorder* r : {&r50, &r30, &r30b, &r12, &r0, &r50b}) pairs.join(*r);
        pairs.join(r30);  // twice in a step counts once
        EXPECT_EQ(pairs.joined(), 6u);
        pairs.run(ctx);
        EXPECT_EQ(pairs.joined(), 0u);
        EXPECT_EQ(pairs.sweeps(), ++sweeps);  // one sweep for all six, by the first of the largest radius
        EXPECT_GT(r50.swept.load(), 0);
        for (Recorder* r : {&r30, &r30b, &r12, &r0, &r50b}) EXPECT_EQ(r->swept.load(), 0);
        for (Recorder* r : {&r50, &r30, &r30b, &r12, &r0, &r50b}) {
            ASSERT_EQ(r->got, within(scene.snapshot(), r->pairRadius()))
                << "radius " << r->pairRadius() << (parallel ? " on the pool" : " alone");
            EXPECT_EQ(r->runs, static_cast<int>(sweeps));
        }
    }
    // The lattice puts pairs exactly on both radii: a filter that loses them (< for <=) fails above.
    const auto onRadius = [&](double r) {
        return std::count_if(r30.got.begin(), r30.got.end(), [&](const Pair& p) {
            const double dx = scene.snapshot().positions()(0, p.second) - scene.snapshot().positions()(0, p.first);
            const double dy = scene.snapshot().positions()(1, p.second) - scene.snapshot().positions()(1, p.first);
            return dx * dx + dy * dy == r * r;
        });
    };
    EXPECT_GT(onRadius(30), 20);
    EXPECT_GT(r50.got.size(), 2 * r30.got.size());
    EXPECT_FALSE(r0.got.empty());  // lattice vehicles on one spot
    // A run with nobody joined sweeps nothing.
    pairs.run(EvaluationContext(scene.snapshot(), scene.grid()));
    EXPECT_EQ(pairs.sweeps(), sweeps);
    // The next step's users alone: the one left out gets nothing new.
    pairs.join(r12);
    pairs.run(EvaluationContext(scene.snapshot(), scene.grid(), nullptr, &pool));
    EXPECT_EQ(r12.runs, 3);
    EXPECT_EQ(r30.runs, 2);
}

TEST(StepPairs, TtcAndSpeedDifferenceOnTheBoardsSweepAnswerAsAlone) {
    // The board's pass: TTC (50 m) and two speed differences (30 m and 50 m) join one shared sweep
    // in prepare(); their answers equal TTC vehicle by vehicle and speed difference's definition.
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> coordinate(0, 300);
    std::uniform_real_distribution<double> unit(0, 1);
    std::uniform_int_distribution<int> speedStep(0, 60);  // quarter m/s: ties and exact differences
    std::vector<Vehicle> steps[3];
    for (int k = 0; k < 700; ++k) {
        // Half on a 10 m lattice (pairs exactly 30 and 50 m apart), a fifth standing.
        const bool lattice = k % 2 == 0;
        double x = lattice ? 10.0 * std::round(coordinate(rng) / 10) : coordinate(rng);
        double y = lattice ? 10.0 * std::round(coordinate(rng) / 10) : coordinate(rng);
        const double speed = unit(rng) < 0.2 ? 0 : 0.25 * speedStep(rng);
        double angle = 90.0 * std::floor(4 * unit(rng));
        const double turn = unit(rng) < 0.7 ? 0 : 30 * unit(rng) - 15;  // degrees per step
        for (auto& step : steps) {
            step.push_back(car("v" + std::to_string(k), x, y, speed, angle, 4 + 3 * unit(rng)));
            const auto ahead = 0.5 * speed * geometry::Footprint::headingOf(angle);
            x += lattice ? 10.0 * std::round(ahead.x() / 10) : ahead.x();
            y += lattice ? 10.0 * std::round(ahead.y() / 10) : ahead.y();
            angle += turn;
        }
    }
    kernel::ParallelFor pool(2);
    StepPairs pairs;
    StepNeighbours lazy;
    TtcCondition ttc(3, 50);
    TtcCondition oneByOne(3, 50);
    SpeedDifferenceConditionSlower slower(2.5, 30);
    SpeedDifferenceConditionFaster faster(0, 50);
    std::size_t conflicts = 0, slowerFound = 0;
    for (int t = 0; t < 3; ++t) {
        Scene scene(steps[t], SimTime::fromSeconds(0.5 * t), 50);
        lazy.reset(scene.snapshot(), 50);
        const EvaluationContext board(scene.snapshot(), lazy, nullptr, &pool, nullptr, nullptr, &pairs);
        const std::size_t before = pairs.sweeps();
        for (Condition* c : std::initializer_list<Condition*>{&ttc, &slower, &faster}) c->prepare(board);
        // From the second step on (when every vehicle was asked about) all three join one sweep.
        EXPECT_EQ(pairs.joined(), t > 0 ? 3u : 0u) << "step " << t;
        pairs.run(board);
        EXPECT_EQ(pairs.sweeps(), before + (t > 0 ? 1 : 0)) << "step " << t;
        EXPECT_EQ(ttc.pairsTestedAhead(), t > 0);
        EXPECT_EQ(slower.answersAhead(), t > 0);
        EXPECT_EQ(faster.answersAhead(), t > 0);
        oneByOne.prepare(scene.ctx());
        for (VehicleIndex ego = 0; ego < scene.snapshot().size(); ++ego) {
            const ConditionResult r = ttc.test(board, ego);
            ASSERT_EQ(r.others(), oneByOne.test(scene.ctx(), ego).others()) << "step " << t << " ego " << ego;
            conflicts += r.others().size();
            const auto expect = [&](bool egoFaster, double delta, double distance) {
                std::vector<VehicleIndex> out;
                const double e = scene.snapshot().speeds()[ego];
                for (VehicleIndex o = 0; o < scene.snapshot().size(); ++o) {
                    const double diff = egoFaster ? e - scene.snapshot().speeds()[o] : scene.snapshot().speeds()[o] - e;
                    const double dx = scene.snapshot().positions()(0, o) - scene.snapshot().positions()(0, ego);
                    const double dy = scene.snapshot().positions()(1, o) - scene.snapshot().positions()(1, ego);
                    if (o != ego && diff > delta && dx * dx + dy * dy <= distance * distance) out.push_back(o);
                }
                return out;
            };
            const ConditionResult s = slower.test(board, ego);
            ASSERT_EQ(s.others(), expect(false, 2.5, 30)) << "step " << t << " ego " << ego;
            ASSERT_EQ(faster.test(board, ego).others(), expect(true, 0, 50)) << "step " << t << " ego " << ego;
            slowerFound += s.others().size();
        }
    }
    EXPECT_GT(conflicts, 50u);
    EXPECT_GT(slowerFound, 1000u);
}

}  // namespace
}  // namespace sbsim::storyboard::test
