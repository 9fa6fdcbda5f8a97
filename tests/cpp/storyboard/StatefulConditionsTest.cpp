#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "StoryboardTestSupport.h"
#include "TestPrinters.h"
#include "sbsim/kernel/RandomStream.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/CarSetCondition.h"
#include "sbsim/storyboard/conditions/DeferringCondition.h"
#include "sbsim/storyboard/conditions/LikelihoodCondition.h"
#include "sbsim/storyboard/conditions/LimitCondition.h"

namespace sbsim::storyboard::test {
namespace {

using kernel::RandomStream;

std::vector<Vehicle> fleet(int n) {
    std::vector<Vehicle> vehicles;
    for (int k = 0; k < n; ++k) vehicles.push_back(car("car" + std::to_string(1000 + k), 10.0 * k, 0));
    return vehicles;
}

TEST(LimitCondition, AdmitsTheFirstVehiclesInEvaluationOrderAndKeepsThem) {
    LimitCondition c(2);
    Scene scene({car("a", 0, 0), car("b", 10, 0), car("c", 20, 0)});
    EXPECT_TRUE(scene.test(c, "c"));
    EXPECT_TRUE(scene.test(c, "a"));
    EXPECT_FALSE(scene.test(c, "b"));
    EXPECT_EQ(c.admittedCount(), 2u);
    // Later steps: the same two, whatever the order.
    for (int step = 1; step <= 3; ++step) {
        scene.set({car("a", 0, 0), car("b", 10, 0), car("c", 20, 0), car("d", 30, 0)}, SimTime::fromSeconds(step));
        EXPECT_FALSE(scene.test(c, "b"));
        EXPECT_FALSE(scene.test(c, "d"));
        EXPECT_TRUE(scene.test(c, "a"));
        EXPECT_TRUE(scene.test(c, "c"));
    }
}

TEST(LimitCondition, ForgettingFreesNoSlot) {
    LimitCondition c(2);
    Scene scene({car("a", 0, 0), car("b", 10, 0), car("c", 20, 0)});
    EXPECT_TRUE(scene.test(c, "a"));
    EXPECT_TRUE(scene.test(c, "b"));
    c.forget("a");
    EXPECT_EQ(c.admittedCount(), 2u);
    EXPECT_FALSE(scene.test(c, "c"));  // a's slot stays used
    EXPECT_FALSE(scene.test(c, "a"));  // and a itself is no longer admitted
    EXPECT_TRUE(scene.test(c, "b"));
    c.forget("unknown");
    EXPECT_TRUE(scene.test(c, "b"));
}

TEST(LimitCondition, ZeroAdmitsNobodyAndNegativeIsRejected) {
    LimitCondition zero(0);
    Scene scene({car("a", 0, 0)});
    EXPECT_FALSE(scene.test(zero, "a"));
    EXPECT_THROW(LimitCondition(-1), std::invalid_argument);
}

TEST(LimitCondition, CountsOnlyVehiclesThatReachIt) {
    // Behind an And, only vehicles passing the left side use up the limit.
    const auto limit = std::make_shared<LimitCondition>(1);
    AndCondition c(std::make_shared<CarSetCondition>(std::set<std::string>{"b", "c"}), limit);
    Scene scene({car("a", 0, 0), car("b", 10, 0), car("c", 20, 0)});
    EXPECT_FALSE(scene.test(c, "a"));
    EXPECT_TRUE(scene.test(c, "b"));
    EXPECT_FALSE(scene.test(c, "c"));
    EXPECT_EQ(limit->admittedCount(), 1u);
}

std::vector<bool> likelihoodDecisions(std::uint64_t seed, unsigned index, double p, Scene& scene) {
    LikelihoodCondition c(std::make_shared<RandomStream>(seed, index), p);
    std::vector<bool> decisions;
    for (const std::string& id : scene.snapshot().ids()) decisions.push_back(scene.test(c, id).isTrue());
    return decisions;
}

TEST(LikelihoodCondition, DrawsOncePerVehicleInEvaluationOrder) {
    const auto rng = std::make_shared<RandomStream>(11, 4);
    LikelihoodCondition c(rng, 0.3);
    Scene scene(fleet(500));
    RandomStream reference(11, 4);
    int admitted = 0;
    for (const std::string& id : scene.snapshot().ids()) {
        const bool expected = reference.uniform01() < 0.3;
        ASSERT_EQ(scene.test(c, id).isTrue(), expected) << id;
        admitted += expected;
    }
    EXPECT_NEAR(admitted / 500.0, 0.3, 0.07);
    // Asking again draws nothing and answers the same.
    const double next = RandomStream(reference).uniform01();
    for (const std::string& id : scene.snapshot().ids()) scene.test(c, id);
    EXPECT_EQ(rng->uniform01(), next);
}

TEST(LikelihoodCondition, IsDeterministicPerSeedAndIndependentPerStream) {
    Scene scene(fleet(300));
    const std::vector<bool> first = likelihoodDecisions(99, 0, 0.5, scene);
    EXPECT_EQ(likelihoodDecisions(99, 0, 0.5, scene), first);
    EXPECT_NE(likelihoodDecisions(99, 1, 0.5, scene), first);
    EXPECT_NE(likelihoodDecisions(100, 0, 0.5, scene), first);
}

TEST(LikelihoodCondition, ClampsTheProbability) {
    Scene scene(fleet(100));
    EXPECT_EQ(likelihoodDecisions(1, 0, 1.0, scene), std::vector<bool>(100, true));
    EXPECT_EQ(likelihoodDecisions(1, 0, 7.0, scene), std::vector<bool>(100, true));
    EXPECT_EQ(likelihoodDecisions(1, 0, 0.0, scene), std::vector<bool>(100, false));
    EXPECT_EQ(likelihoodDecisions(1, 0, -2.0, scene), std::vector<bool>(100, false));
    EXPECT_EQ(LikelihoodCondition(std::make_shared<RandomStream>(1, 0), 3).probability(), 1.0);
    EXPECT_THROW(LikelihoodCondition(std::make_shared<RandomStream>(1, 0), std::nan("")), std::invalid_argument);
    EXPECT_THROW(LikelihoodCondition(nullptr, 0.5), std::invalid_argument);
}

TEST(LikelihoodCondition, ForgetDropsTheDecision) {
    const auto rng = std::make_shared<RandomStream>(3, 0);
    LikelihoodCondition c(rng, 0.5);
    Scene scene({car("a", 0, 0)});
    scene.test(c, "a");
    RandomStream reference(*rng);
    scene.test(c, "a");  // remembered: no draw
    c.forget("a");
    const bool redrawn = reference.uniform01() < 0.5;
    EXPECT_EQ(scene.test(c, "a").isTrue(), redrawn);
    EXPECT_EQ(rng->uniform01(), reference.uniform01());  // exactly one draw happened
}

TEST(DeferringCondition, BecomesTrueAfterTheDrawnDeferral) {
    const auto rng = std::make_shared<RandomStream>(5, 2);
    DeferringCondition c(rng, SimTime::fromSeconds(1), SimTime::fromSeconds(5));
    RandomStream reference(5, 2);
    const SimTime first = SimTime::fromSeconds(10);
    const SimTime due = first + SimTime::fromSeconds(1) + SimTime::fromRaw(std::llround(4e9 * reference.uniform01()));
    ASSERT_GT(due, first + SimTime::fromSeconds(1));

    Scene scene({car("a", 0, 0)}, first);
    EXPECT_FALSE(scene.test(c, "a"));
    const auto at = [&](SimTime t) {
        scene.set({car("a", 0, 0)}, t);
        return scene.test(c, "a").isTrue();
    };
    EXPECT_FALSE(at(first + SimTime::fromSeconds(1)));
    EXPECT_FALSE(at(due - SimTime::fromNanoseconds(1)));
    EXPECT_TRUE(at(due));
    EXPECT_TRUE(at(due + SimTime::fromSeconds(100)));
}

TEST(DeferringCondition, FixedDeferral) {
    DeferringCondition c(std::make_shared<RandomStream>(1, 0), SimTime::fromSeconds(2), SimTime::fromSeconds(2));
    Scene scene({car("a", 0, 0), car("b", 5, 0)}, SimTime::fromSeconds(1));
    EXPECT_FALSE(scene.test(c, "a"));
    scene.set({car("a", 0, 0), car("b", 5, 0)}, SimTime::fromSeconds(2));
    EXPECT_FALSE(scene.test(c, "a"));
    EXPECT_FALSE(scene.test(c, "b"));  // b's clock starts now
    scene.set({car("a", 0, 0), car("b", 5, 0)}, SimTime::fromSeconds(3));
    EXPECT_TRUE(scene.test(c, "a"));
    EXPECT_FALSE(scene.test(c, "b"));
    scene.set({car("a", 0, 0), car("b", 5, 0)}, SimTime::fromSeconds(4));
    EXPECT_TRUE(scene.test(c, "b"));
}

TEST(DeferringCondition, ZeroDeferralIsTrueAtOnce) {
    DeferringCondition c(std::make_shared<RandomStream>(1, 0), SimTime::zero(), SimTime::zero());
    Scene scene({car("a", 0, 0)}, SimTime::fromSeconds(7));
    EXPECT_TRUE(scene.test(c, "a"));
}

std::vector<bool> deferredAt(unsigned index, SimTime probe, const Scene& start, Scene& later) {
    DeferringCondition c(std::make_shared<RandomStream>(8, index), SimTime::zero(), SimTime::fromSeconds(10));
    for (const std::string& id : start.snapshot().ids()) start.test(c, id);
    std::vector<bool> due;
    later.set(fleet(200), probe);
    for (const std::string& id : later.snapshot().ids()) due.push_back(later.test(c, id).isTrue());
    return due;
}

TEST(DeferringCondition, IsDeterministicPerSeedAndIndependentPerStream) {
    const Scene start(fleet(200));
    Scene later(fleet(200));
    const std::vector<bool> first = deferredAt(0, SimTime::fromSeconds(5), start, later);
    EXPECT_EQ(deferredAt(0, SimTime::fromSeconds(5), start, later), first);
    EXPECT_NE(deferredAt(1, SimTime::fromSeconds(5), start, later), first);
    const auto due = static_cast<double>(std::count(first.begin(), first.end(), true));
    EXPECT_NEAR(due / 200, 0.5, 0.12);
}

TEST(DeferringCondition, ForgetDropsTheDeadline) {
    DeferringCondition c(std::make_shared<RandomStream>(1, 0), SimTime::fromSeconds(2), SimTime::fromSeconds(2));
    Scene scene({car("a", 0, 0)}, SimTime::fromSeconds(0));
    EXPECT_FALSE(scene.test(c, "a"));
    scene.set({car("a", 0, 0)}, SimTime::fromSeconds(2));
    c.forget("a");
    EXPECT_FALSE(scene.test(c, "a"));  // a new deadline, 4 s
    scene.set({car("a", 0, 0)}, SimTime::fromSeconds(3));
    EXPECT_FALSE(scene.test(c, "a"));
    scene.set({car("a", 0, 0)}, SimTime::fromSeconds(4));
    EXPECT_TRUE(scene.test(c, "a"));
}

TEST(DeferringCondition, RejectsBadParameters) {
    const auto rng = std::make_shared<RandomStream>(1, 0);
    EXPECT_THROW(DeferringCondition(rng, SimTime::fromSeconds(3), SimTime::fromSeconds(2)), std::invalid_argument);
    EXPECT_THROW(DeferringCondition(rng, SimTime::fromSeconds(-1), SimTime::fromSeconds(2)), std::invalid_argument);
    EXPECT_THROW(DeferringCondition(nullptr, SimTime::zero(), SimTime::zero()), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::storyboard::test
