#include "sbsim/storyboard/conditions/SpeedDifferenceCondition.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>

#include "StoryboardTestSupport.h"
#include "sbsim/kernel/ParallelFor.h"

namespace sbsim::storyboard::test {
namespace {

TEST(SpeedDifferenceCondition, FasterIsStrictAndCoversAllVehiclesWithoutDistance) {
    Scene scene({car("ego", 0, 0, 20), car("slow", 10, 0, 10), car("exact", 20, 0, 15), car("fast", 30, 0, 25),
                 car("farSlow", 50'000, 0, 5)});
    SpeedDifferenceConditionFaster c(5);
    EXPECT_FALSE(c.neighbourRadius());
    const ConditionResult r = scene.test(c, "ego");
    EXPECT_TRUE(r.isSet());
    EXPECT_EQ(scene.others(r), (Ids{"farSlow", "slow"}));  // ascending id order
    // From the slowest vehicle's view nobody is slower.
    const ConditionResult none = scene.test(c, "farSlow");
    EXPECT_TRUE(none.isSet());
    EXPECT_FALSE(none.isTrue());
}

TEST(SpeedDifferenceCondition, SlowerIsStrict) {
    Scene scene({car("ego", 0, 0, 20), car("slow", 10, 0, 10), car("exact", 20, 0, 25), car("fast", 30, 0, 25.5),
                 car("faster", 40, 0, 40)});
    SpeedDifferenceConditionSlower c(5);
    EXPECT_EQ(scene.others(scene.test(c, "ego")), (Ids{"fast", "faster"}));
    EXPECT_EQ(scene.others(scene.test(c, "slow")), (Ids{"ego", "exact", "fast", "faster"}));
}

TEST(SpeedDifferenceCondition, NeverContainsTheEgo) {
    Scene scene({car("a", 0, 0, 10), car("b", 10, 0, 10)});
    SpeedDifferenceConditionFaster all(-1);  // every speed difference of 0 qualifies
    EXPECT_EQ(scene.others(scene.test(all, "a")), (Ids{"b"}));
    SpeedDifferenceConditionSlower near(-1, 20);
    EXPECT_EQ(scene.others(scene.test(near, "a")), (Ids{"b"}));
}

TEST(SpeedDifferenceCondition, DistanceIsInclusive) {
    Scene scene(
        {car("ego", 0, 0, 20), car("edge", 30, 40, 0), car("beyond", 30, 40.001, 0), car("fastNear", 1, 1, 30)});
    SpeedDifferenceConditionFaster c(5, 50.0);
    EXPECT_EQ(c.neighbourRadius(), 50.0);
    EXPECT_EQ(scene.others(scene.test(c, "ego")), (Ids{"edge"}));
    SpeedDifferenceConditionSlower slower(5, 50.0);
    EXPECT_EQ(scene.others(scene.test(slower, "ego")), (Ids{"fastNear"}));
}

TEST(SpeedDifferenceCondition, RejectsBadParameters) {
    EXPECT_THROW(SpeedDifferenceConditionFaster(std::nan("")), std::invalid_argument);
    EXPECT_THROW(SpeedDifferenceConditionFaster(1, -1.0), std::invalid_argument);
    EXPECT_THROW(SpeedDifferenceConditionSlower(1, std::numeric_limits<double>::infinity()), std::invalid_argument);
    EXPECT_NO_THROW(SpeedDifferenceConditionSlower(1, 0.0));
}

/// The definition, pair by pair.
std::vector<VehicleIndex> bruteForce(const traffic::VehicleSnapshot& s, VehicleIndex ego, bool egoFaster, double delta,
                                     std::optional<double> distance) {
    std::vector<VehicleIndex> out;
    const double e = s.speeds()[ego];
    for (VehicleIndex o = 0; o < s.size(); ++o) {
        if (o == ego) continue;
        const double diff = egoFaster ? e - s.speeds()[o] : s.speeds()[o] - e;
        const double dx = s.positions()(0, o) - s.positions()(0, ego);
        const double dy = s.positions()(1, o) - s.positions()(1, ego);
        if (diff > delta && (!distance || dx * dx + dy * dy <= *distance * *distance)) out.push_back(o);
    }
    return out;
}

TEST(SpeedDifferenceCondition, MatchesBruteForceOnRandomTraffic) {
    std::mt19937_64 rng(31337);
    std::uniform_real_distribution<double> coordinate(0, 600);
    std::uniform_int_distribution<int> speedStep(0, 60);  // quarter m/s steps: many ties and exact differences
    std::vector<Vehicle> vehicles;
    for (int k = 0; k < 700; ++k) {
        vehicles.push_back(car("veh" + std::to_string(k), coordinate(rng), coordinate(rng), 0.25 * speedStep(rng)));
    }
    Scene scene(vehicles, SimTime::fromSeconds(1), 60);
    std::size_t nonEmpty = 0;
    for (const std::optional<double> distance : {std::optional<double>(), std::optional<double>(60.0)}) {
        for (const double delta : {-100.0, -0.25, 0.0, 2.5, 7.0, 14.75}) {
            SpeedDifferenceConditionFaster faster(delta, distance);
            SpeedDifferenceConditionSlower slower(delta, distance);
            faster.prepare(scene.ctx());
            slower.prepare(scene.ctx());
            for (VehicleIndex ego = 0; ego < scene.snapshot().size(); ego += 3) {
                const ConditionResult f = faster.test(scene.ctx(), ego);
                const ConditionResult s = slower.test(scene.ctx(), ego);
                ASSERT_EQ(f.others(), bruteForce(scene.snapshot(), ego, true, delta, distance))
                    << "ego " << ego << " delta " << delta;
                ASSERT_EQ(s.others(), bruteForce(scene.snapshot(), ego, false, delta, distance))
                    << "ego " << ego << " delta " << delta;
                nonEmpty += f.isTrue() + s.isTrue();
            }
        }
    }
    EXPECT_GT(nonEmpty, 1000u);
}

TEST(SpeedDifferenceCondition, AnswersAheadWithAPoolMatchBruteForce) {
    // With a distance and a pool, prepare() finds every answer at once (one sweep of the pairs)
    // once test() asked about most vehicles in the step before; the answers are the definition's.
    std::mt19937_64 rng(4711);
    std::uniform_real_distribution<double> coordinate(-300, 300);
    std::uniform_int_distribution<int> speedStep(0, 60);  // quarter m/s steps: ties and exact differences
    std::vector<Vehicle> steps[3];
    for (int k = 0; k < 800; ++k) {
        for (int t = 0; t < 3; ++t) {
            // Lattice positions in the last step: pairs exactly on the distance and on cell borders.
            const double x = t == 2 ? 10.0 * std::round(coordinate(rng) / 10) : coordinate(rng);
            const double y = t == 2 ? 10.0 * std::round(coordinate(rng) / 10) : coordinate(rng);
            const double speed = k == 7 ? std::numeric_limits<double>::quiet_NaN() : 0.25 * speedStep(rng);
            steps[t].push_back(car("veh" + std::to_string(k), x, y, speed));
        }
    }
    kernel::ParallelFor pool(2);
    std::size_t nonEmpty = 0;
    for (const double distance : {30.0, 50.0}) {
        for (const double delta : {-0.25, 0.0, 2.5, 8.0}) {
            SpeedDifferenceConditionFaster faster(delta, distance);
            SpeedDifferenceConditionSlower slower(delta, distance);
            for (int t = 0; t < 3; ++t) {
                Scene scene(steps[t], SimTime::fromSeconds(t), 50);
                const EvaluationContext pooled(scene.snapshot(), scene.grid(), nullptr, &pool);
                faster.prepare(pooled);
                slower.prepare(pooled);
                EXPECT_EQ(faster.answersAhead(), t > 0) << "step " << t;  // nothing asked before step 0
                EXPECT_EQ(slower.answersAhead(), t > 0) << "step " << t;
                for (VehicleIndex ego = 0; ego < scene.snapshot().size(); ++ego) {
                    const ConditionResult f = faster.test(pooled, ego);
                    const ConditionResult s = slower.test(pooled, ego);
                    ASSERT_EQ(f.others(), bruteForce(scene.snapshot(), ego, true, delta, distance))
                        << "step " << t << " ego " << ego << " delta " << delta << " distance " << distance;
                    ASSERT_EQ(s.others(), bruteForce(scene.snapshot(), ego, false, delta, distance))
                        << "step " << t << " ego " << ego << " delta " << delta << " distance " << distance;
                    nonEmpty += f.isTrue() + s.isTrue();
                }
            }
            // Asked about one vehicle only: the next step searches per ego again.
            Scene few(steps[0], SimTime::fromSeconds(3), 50);
            const EvaluationContext pooledFew(few.snapshot(), few.grid(), nullptr, &pool);
            faster.prepare(pooledFew);
            EXPECT_TRUE(faster.answersAhead());
            ASSERT_EQ(faster.test(pooledFew, 0).others(), bruteForce(few.snapshot(), 0, true, delta, distance));
            Scene next(steps[1], SimTime::fromSeconds(4), 50);
            const EvaluationContext pooledNext(next.snapshot(), next.grid(), nullptr, &pool);
            faster.prepare(pooledNext);
            EXPECT_FALSE(faster.answersAhead());
            ASSERT_EQ(faster.test(pooledNext, 5).others(), bruteForce(next.snapshot(), 5, true, delta, distance));
        }
    }
    EXPECT_GT(nonEmpty, 5000u);
}

TEST(SpeedDifferenceCondition, WithADistanceTheStepsExtremeSpeedsSpareTheSearch) {
    // prepare() keeps the step's lowest and highest speed (a NaN skipped): an ego that no speed
    // of the step can differ from by more than delta is answered without a neighbour search.
    // They must be this step's own: here the slowest and the fastest are the first and the last.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Scene scene({car("a", 0, 0, 1), car("m", 5, 0, nan), car("n", 8, 0, 6), car("z", 10, 0, 11)},
                SimTime::fromSeconds(1));
    SpeedDifferenceConditionSlower slower(4.5, 50);
    SpeedDifferenceConditionFaster faster(4.5, 50);
    slower.prepare(scene.ctx());
    faster.prepare(scene.ctx());
    const auto others = [&](Condition& c, const char* id) {
        return scene.others(c.test(scene.ctx(), scene.index(id)));
    };
    EXPECT_EQ(others(slower, "a"), (Ids{"n", "z"}));
    EXPECT_EQ(others(slower, "n"), (Ids{"z"}));
    EXPECT_EQ(others(slower, "z"), (Ids{}));
    EXPECT_EQ(others(slower, "m"), (Ids{}));
    EXPECT_EQ(others(faster, "z"), (Ids{"a", "n"}));
    EXPECT_EQ(others(faster, "n"), (Ids{"a"}));
    EXPECT_EQ(others(faster, "a"), (Ids{}));
    // A new step not prepared for: the last step's extremes (1 and 11 m/s) no longer hold, and
    // n, 4 m/s below the old highest, now has one 13 m/s faster.
    scene.set({car("a", 0, 0, 1), car("n", 8, 0, 7), car("z", 10, 0, 20)}, SimTime::fromSeconds(2));
    EXPECT_EQ(others(slower, "n"), (Ids{"z"}));
    EXPECT_EQ(others(faster, "n"), (Ids{"a"}));
}

TEST(SpeedDifferenceCondition, FollowsANewSnapshotEvenWithoutPrepare) {
    SpeedDifferenceConditionFaster c(1);
    Scene scene({car("a", 0, 0, 10), car("b", 5, 0, 5)}, SimTime::fromSeconds(1));
    EXPECT_EQ(scene.others(c.test(scene.ctx(), scene.index("a"))), (Ids{"b"}));
    scene.set({car("a", 0, 0, 10), car("b", 5, 0, 12), car("c", 9, 0, 2)}, SimTime::fromSeconds(2));
    EXPECT_EQ(scene.others(c.test(scene.ctx(), scene.index("a"))), (Ids{"c"}));
}

}  // namespace
}  // namespace sbsim::storyboard::test
