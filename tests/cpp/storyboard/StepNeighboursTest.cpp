#include "sbsim/storyboard/StepNeighbours.h"

#include <gtest/gtest.h>

#include <atomic>
#include <random>
#include <string>
#include <vector>

#include "StoryboardTestSupport.h"
#include "sbsim/kernel/ParallelFor.h"
#include "sbsim/storyboard/conditions/SpeedDifferenceCondition.h"
#include "sbsim/storyboard/conditions/TtcCondition.h"

namespace sbsim::storyboard::test {
namespace {

std::vector<Vehicle> randomCars(std::uint32_t seed, int count) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coordinate(0, 400);
    std::uniform_int_distribution<int> speed(0, 40);
    std::uniform_int_distribution<int> heading(0, 3);
    std::vector<Vehicle> cars;
    for (int k = 0; k < count; ++k) {
        cars.push_back(
            car("veh" + std::to_string(k), coordinate(rng), coordinate(rng), 0.5 * speed(rng), 90.0 * heading(rng)));
    }
    return cars;
}

TEST(StepNeighbours, BuiltOnlyWhenAskedOncePerStepAndForThatStepsSnapshot) {
    traffic::VehicleSnapshot first;
    traffic::VehicleSnapshot second;
    first.assign(randomCars(1, 300), SimTime::fromSeconds(1));
    second.assign(randomCars(2, 300), SimTime::fromSeconds(2));
    traffic::NeighbourGrid expectFirst;
    traffic::NeighbourGrid expectSecond;
    expectFirst.build(first, 30);
    expectSecond.build(second, 30);

    StepNeighbours lazy;
    lazy.reset(first, 30);
    EXPECT_FALSE(lazy.built());
    EXPECT_EQ(lazy.builds(), 0u);
    const EvaluationContext ctx(first, lazy);
    EXPECT_FALSE(lazy.built());  // a context alone builds nothing

    // Many threads ask at once: one build, every answer the grid's.
    kernel::ParallelFor pool(4);
    std::atomic<int> wrong{0};
    pool.run(
        300,
        [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const auto ego = static_cast<VehicleIndex>(i);
                if (ctx.neighbours().within(ego, 30) != expectFirst.within(ego, 30)) ++wrong;
            }
        },
        1);
    EXPECT_EQ(wrong.load(), 0);
    EXPECT_TRUE(lazy.built());
    EXPECT_EQ(lazy.builds(), 1u);

    // The next step: nothing until asked, then the new snapshot's grid, not the old one's.
    lazy.reset(second, 30);
    EXPECT_FALSE(lazy.built());
    const EvaluationContext next(second, lazy);
    std::size_t differing = 0;
    for (VehicleIndex ego = 0; ego < second.size(); ++ego) {
        ASSERT_EQ(next.neighbours().within(ego, 30), expectSecond.within(ego, 30)) << ego;
        differing += expectFirst.within(ego, 30) != expectSecond.within(ego, 30);
    }
    EXPECT_GT(differing, 100u);  // a grid kept from the first step would have failed above
    EXPECT_EQ(lazy.builds(), 2u);
}

TEST(StepNeighbours, TheSearchingConditionsAnsweringAheadLeaveItUnbuilt) {
    // The board's steady state: TTC and speed difference, asked about every vehicle each step,
    // answer from their own sweeps after the first step, so the grid is built in the first only.
    kernel::ParallelFor pool(2);
    TtcCondition ttc(2.0, 50.0);
    SpeedDifferenceConditionSlower slower(4.0, 30.0);
    StepNeighbours lazy;
    for (int t = 0; t < 3; ++t) {
        traffic::VehicleSnapshot snapshot;
        snapshot.assign(randomCars(10 + static_cast<std::uint32_t>(t), 400), SimTime::fromSeconds(t));
        lazy.reset(snapshot, 50);
        const EvaluationContext ctx(snapshot, lazy, nullptr, &pool);
        ttc.prepare(ctx);
        slower.prepare(ctx);
        std::size_t found = 0;
        for (VehicleIndex ego = 0; ego < snapshot.size(); ++ego) {
            found += ttc.test(ctx, ego).others().size() + slower.test(ctx, ego).others().size();
        }
        EXPECT_GT(found, 0u);
        EXPECT_EQ(lazy.built(), t == 0) << "step " << t;
        EXPECT_EQ(ttc.pairsTestedAhead(), t > 0) << "step " << t;
        EXPECT_EQ(slower.answersAhead(), t > 0) << "step " << t;
    }
    EXPECT_EQ(lazy.builds(), 1u);
}

}  // namespace
}  // namespace sbsim::storyboard::test
