// Story logic: Not, All/Any (n-ary, lazy, And/Or's set rules), Hold and Rising (per-vehicle runs
// of true steps, reset by a false or skipped step, dropped when the vehicle leaves), Latch (true
// for good once true, until the vehicle leaves).

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "StoryboardTestSupport.h"
#include "sbsim/storyboard/conditions/AllCondition.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/AnyCondition.h"
#include "sbsim/storyboard/conditions/HoldCondition.h"
#include "sbsim/storyboard/conditions/LatchCondition.h"
#include "sbsim/storyboard/conditions/LimitCondition.h"
#include "sbsim/storyboard/conditions/NotCondition.h"
#include "sbsim/storyboard/conditions/OrCondition.h"
#include "sbsim/storyboard/conditions/RisingCondition.h"
#include "sbsim/storyboard/conditions/SpeedCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"

namespace sbsim::storyboard::test {
namespace {

using Set = std::vector<VehicleIndex>;

std::shared_ptr<ProbeCondition> probe(ConditionResult r) { return std::make_shared<ProbeCondition>(std::move(r)); }
ConditionResult set(Set s) { return ConditionResult::ofOthers(std::move(s)); }

class StoryLogic : public ::testing::Test {
protected:
    Scene scene{{car("a", 0, 0), car("b", 10, 0), car("c", 20, 0), car("d", 30, 0)}};
};

TEST_F(StoryLogic, NotOfASetIsAPlainBool) {
    NotCondition ofSet(probe(set({1, 2})));
    const ConditionResult r = scene.test(ofSet, "a");
    EXPECT_FALSE(r);
    EXPECT_FALSE(r.isSet());
    NotCondition ofEmpty(probe(set({})));
    const ConditionResult e = scene.test(ofEmpty, "a");
    EXPECT_TRUE(e);
    EXPECT_FALSE(e.isSet());
    EXPECT_TRUE(scene.test(*std::make_shared<NotCondition>(probe(false)), "a"));
    EXPECT_FALSE(scene.test(*std::make_shared<NotCondition>(probe(true)), "a"));
    EXPECT_THROW(NotCondition(nullptr), std::invalid_argument);
}

TEST_F(StoryLogic, AllStopsAtTheFirstFalseOperandAndIntersectsSets) {
    const auto first = probe(set({1, 2, 3}));
    const auto second = probe(true);
    const auto third = probe(set({2, 3}));
    const auto fourth = probe(set({3}));
    AllCondition all({first, second, third, fourth});
    const ConditionResult r = scene.test(all, "a");
    EXPECT_TRUE(r.isSet());
    EXPECT_EQ(r.others(), (Set{3}));
    EXPECT_EQ(fourth->calls, 1);

    const auto empty = probe(set({}));
    const auto after = probe(true);
    AllCondition stops({probe(true), empty, after});
    EXPECT_FALSE(scene.test(stops, "a"));
    EXPECT_EQ(after->calls, 0) << "nothing after the first false operand is evaluated";
    AllCondition disjoint({probe(set({1})), probe(set({2})), after});
    EXPECT_FALSE(scene.test(disjoint, "a"));
    EXPECT_EQ(after->calls, 0) << "an empty intersection is false and stops the evaluation";
    EXPECT_THROW(AllCondition({}), std::invalid_argument);
    EXPECT_THROW(AllCondition({probe(true), nullptr}), std::invalid_argument);
}

TEST_F(StoryLogic, AnyStopsAtTheFirstTrueOperandAndReturnsIt) {
    const auto empty = probe(set({}));
    const auto falseOne = probe(false);
    const auto hit = probe(set({2}));
    const auto after = probe(set({1, 3}));
    AnyCondition any({empty, falseOne, hit, after});
    const ConditionResult r = scene.test(any, "a");
    EXPECT_EQ(r.others(), (Set{2}));
    EXPECT_EQ(after->calls, 0);
    EXPECT_EQ(empty->calls, 1);
    EXPECT_EQ(falseOne->calls, 1);
    AnyCondition none({probe(false), probe(set({}))});
    EXPECT_FALSE(scene.test(none, "a"));
    EXPECT_THROW(AnyCondition({}), std::invalid_argument);
}

TEST_F(StoryLogic, AllAndAnyAgreeWithNestedAndOr) {
    // Every combination of three operands out of {false, true, empty set, {1}, {1, 2}, {2}}.
    const std::vector<ConditionResult> values{false, true, set({}), set({1}), set({1, 2}), set({2})};
    for (const auto& x : values) {
        for (const auto& y : values) {
            for (const auto& z : values) {
                const auto rx = probe(x), ry = probe(y), rz = probe(z);
                AllCondition all({rx, ry, rz});
                AndCondition nestedAnd(std::make_shared<AndCondition>(rx, ry), rz);
                const ConditionResult a = scene.test(all, "a"), b = scene.test(nestedAnd, "a");
                EXPECT_EQ(a.isTrue(), b.isTrue());
                EXPECT_EQ(a.isSet(), b.isSet());
                EXPECT_EQ(a.others(), b.others());
                AnyCondition any({rx, ry, rz});
                OrCondition nestedOr(std::make_shared<OrCondition>(rx, ry), rz);
                const ConditionResult c = scene.test(any, "a"), d = scene.test(nestedOr, "a");
                EXPECT_EQ(c.isTrue(), d.isTrue());
                EXPECT_EQ(c.isSet(), d.isSet());
                EXPECT_EQ(c.others(), d.others());
            }
        }
    }
}

TEST_F(StoryLogic, PurityFollowsTheOperands) {
    const auto pure = std::make_shared<SpeedConditionGreater>(1.0);
    const auto limit = std::make_shared<LimitCondition>(1);
    EXPECT_TRUE(NotCondition(pure).pure());
    EXPECT_FALSE(NotCondition(limit).pure());
    EXPECT_TRUE(AllCondition({pure, pure}).pure());
    EXPECT_FALSE(AllCondition({pure, limit}).pure());
    EXPECT_TRUE(AnyCondition({pure}).pure());
    EXPECT_FALSE(AnyCondition({limit, pure}).pure());
    EXPECT_FALSE(HoldCondition(pure, SimTime::zero()).pure()) << "it keeps per-vehicle state";
    EXPECT_FALSE(RisingCondition(pure).pure());
}

/// Steps of 1 s with vehicle "a" at the given speeds (one per step, from t = 1).
class Timeline {
public:
    explicit Timeline(Condition& c) : c_(c) {}
    /// The condition's value for "a" at the next step with speed v (and "b" standing beside it).
    ConditionResult next(double v) {
        ++t_;
        scene_.set({car("a", 0, 0, v), car("b", 10, 0, 0)}, SimTime::fromSeconds(t_));
        return scene_.test(c_, "a");
    }
    /// A step at which the condition is prepared but not evaluated for "a".
    void skip() {
        ++t_;
        scene_.set({car("a", 0, 0, 0)}, SimTime::fromSeconds(t_));
        c_.prepare(scene_.ctx());
    }
    const Scene& scene() const { return scene_; }

private:
    Condition& c_;
    Scene scene_{std::vector<Vehicle>{}};
    int t_ = 0;
};

TEST(HoldCondition, TrueAfterTheOperandHeldForTheDurationAndResetByOneFalseStep) {
    HoldCondition hold(std::make_shared<SpeedConditionGreater>(5.0), SimTime::fromSeconds(2));
    Timeline steps(hold);
    EXPECT_FALSE(steps.next(10));  // t=1: held 0 s
    EXPECT_FALSE(steps.next(10));  // t=2: 1 s
    EXPECT_TRUE(steps.next(10));   // t=3: 2 s
    EXPECT_TRUE(steps.next(10));   // t=4
    EXPECT_FALSE(steps.next(1));   // t=5: one false step
    EXPECT_FALSE(steps.next(10));  // t=6: 0 s again
    EXPECT_FALSE(steps.next(10));  // t=7: 1 s
    EXPECT_TRUE(steps.next(10));   // t=8: 2 s
}

TEST(HoldCondition, ZeroDurationIsTheOperandAndNegativeIsRejected) {
    HoldCondition hold(std::make_shared<SpeedConditionGreater>(5.0), SimTime::zero());
    Timeline steps(hold);
    EXPECT_TRUE(steps.next(10));
    EXPECT_FALSE(steps.next(1));
    EXPECT_TRUE(steps.next(10));
    EXPECT_THROW(HoldCondition(std::make_shared<SpeedConditionGreater>(5.0), SimTime::fromSeconds(-1)),
                 std::invalid_argument);
    EXPECT_THROW(HoldCondition(nullptr, SimTime::zero()), std::invalid_argument);
}

TEST(HoldCondition, AStepWithoutEvaluationBreaksTheRun) {
    HoldCondition hold(std::make_shared<SpeedConditionGreater>(5.0), SimTime::fromSeconds(1));
    Timeline steps(hold);
    EXPECT_FALSE(steps.next(10));
    EXPECT_TRUE(steps.next(10));
    steps.skip();  // e.g. an And before it was false: the vehicle was not seen to hold
    EXPECT_FALSE(steps.next(10));
    EXPECT_TRUE(steps.next(10));
}

TEST(HoldCondition, ReturnsTheOperandsSetAndForgetsVehiclesThatLeft) {
    class OthersCondition : public Condition {
    public:
        ConditionResult test(const EvaluationContext& /*ctx*/, VehicleIndex ego) override {
            return ConditionResult::ofOthers(ego == 0 ? std::vector<VehicleIndex>{1} : std::vector<VehicleIndex>{});
        }
    };
    HoldCondition hold(std::make_shared<OthersCondition>(), SimTime::fromSeconds(1));
    Timeline steps(hold);
    EXPECT_FALSE(steps.next(0));
    const ConditionResult r = steps.next(0);
    EXPECT_TRUE(r.isSet());
    EXPECT_EQ(steps.scene().others(r), (Ids{"b"}));
    EXPECT_EQ(hold.tracked(), 1u);
    hold.forget("a");
    EXPECT_EQ(hold.tracked(), 0u);
    EXPECT_FALSE(steps.next(0)) << "a vehicle forgotten starts from 0 s";
}

TEST(HoldCondition, SharedBetweenStoriesAnswersTheSameWithinAStep) {
    HoldCondition hold(std::make_shared<SpeedConditionGreater>(5.0), SimTime::fromSeconds(1));
    Scene scene({car("a", 0, 0, 10)}, SimTime::fromSeconds(1));
    EXPECT_FALSE(scene.test(hold, "a"));
    EXPECT_FALSE(scene.test(hold, "a"));
    scene.set({car("a", 0, 0, 10)}, SimTime::fromSeconds(2));
    EXPECT_TRUE(scene.test(hold, "a"));
    EXPECT_TRUE(scene.test(hold, "a"));
}

TEST(RisingCondition, TrueOnlyAtTheStepTheOperandTurnsTrue) {
    RisingCondition rising(std::make_shared<SpeedConditionGreater>(5.0));
    Timeline steps(rising);
    EXPECT_TRUE(steps.next(10)) << "the first evaluation counts as a rise";
    EXPECT_FALSE(steps.next(10));
    EXPECT_FALSE(steps.next(10));
    EXPECT_FALSE(steps.next(1));
    EXPECT_FALSE(steps.next(1));
    EXPECT_TRUE(steps.next(10));
    EXPECT_FALSE(steps.next(10));
    steps.skip();
    EXPECT_TRUE(steps.next(10)) << "after a step it was not evaluated, true again counts as a rise";
    EXPECT_EQ(rising.tracked(), 1u);
    rising.forget("a");
    EXPECT_EQ(rising.tracked(), 0u);
    EXPECT_THROW(RisingCondition(nullptr), std::invalid_argument);
}

TEST(LatchCondition, OnceTrueForAVehicleStaysTrueUntilItLeaves) {
    LatchCondition latch(std::make_shared<SpeedConditionGreater>(5.0));
    Timeline steps(latch);
    EXPECT_FALSE(steps.next(1));
    EXPECT_FALSE(steps.next(1));
    EXPECT_TRUE(steps.next(10));
    EXPECT_TRUE(steps.next(1)) << "the operand turned false: the latch holds";
    steps.skip();
    EXPECT_TRUE(steps.next(1)) << "a step it was not evaluated changes nothing";
    EXPECT_EQ(latch.heldVehicles(), 1u);
    latch.forget("a");
    EXPECT_EQ(latch.heldVehicles(), 0u);
    EXPECT_FALSE(steps.next(1)) << "a vehicle forgotten starts again";
    EXPECT_THROW(LatchCondition(nullptr), std::invalid_argument);
}

TEST(LatchCondition, YieldsTheOperandsSetWhileItHoldsThenAPlainTrue) {
    class OthersWhileFast : public Condition {
    public:
        ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override {
            if (ctx.snapshot().speeds()[ego] <= 5.0) return false;
            return ConditionResult::ofOthers(std::vector<VehicleIndex>{1});
        }
    };
    const auto operand = std::make_shared<OthersWhileFast>();
    LatchCondition latch(operand);
    Timeline steps(latch);
    const ConditionResult r = steps.next(10);
    ASSERT_TRUE(r.isSet());
    EXPECT_EQ(steps.scene().others(r), (Ids{"b"}));
    const ConditionResult after = steps.next(1);
    EXPECT_TRUE(after);
    EXPECT_FALSE(after.isSet());
    EXPECT_FALSE(latch.pure()) << "it keeps per-vehicle state";
    EXPECT_EQ(latch.describe(), "LatchCondition");
}

}  // namespace
}  // namespace sbsim::storyboard::test
