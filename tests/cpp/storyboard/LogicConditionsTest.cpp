#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "StoryboardTestSupport.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/OrCondition.h"

namespace sbsim::storyboard::test {
namespace {

using Set = std::vector<VehicleIndex>;

std::shared_ptr<ProbeCondition> probe(ConditionResult r) { return std::make_shared<ProbeCondition>(std::move(r)); }

class LogicConditions : public ::testing::Test {
protected:
    Scene scene{{car("a", 0, 0), car("b", 10, 0), car("c", 20, 0), car("d", 30, 0)}};
};

TEST_F(LogicConditions, AndSkipsTheRightSideWhenTheLeftIsFalse) {
    const auto left = probe(false);
    const auto right = probe(true);
    AndCondition c(left, right);
    EXPECT_FALSE(scene.test(c, "a"));
    EXPECT_EQ(left->calls, 1);
    EXPECT_EQ(right->calls, 0);

    const auto emptySet = probe(ConditionResult::ofOthers({}));
    AndCondition c2(emptySet, right);
    EXPECT_FALSE(scene.test(c2, "a"));
    EXPECT_EQ(right->calls, 0);
}

TEST_F(LogicConditions, AndEvaluatesTheRightSideWhenTheLeftIsTrue) {
    const auto left = probe(true);
    const auto right = probe(false);
    AndCondition c(left, right);
    EXPECT_FALSE(scene.test(c, "a"));
    EXPECT_EQ(right->calls, 1);
    AndCondition both(left, probe(true));
    EXPECT_TRUE(scene.test(both, "a"));
}

TEST_F(LogicConditions, AndCombinesSets) {
    AndCondition sets(probe(ConditionResult::ofOthers({1, 2, 3})), probe(ConditionResult::ofOthers({2, 3})));
    const ConditionResult r = scene.test(sets, "a");
    EXPECT_TRUE(r.isSet());
    EXPECT_EQ(r.others(), (Set{2, 3}));
    AndCondition setAndTrue(probe(ConditionResult::ofOthers({1})), probe(true));
    EXPECT_EQ(scene.test(setAndTrue, "a").others(), (Set{1}));
    AndCondition disjoint(probe(ConditionResult::ofOthers({1})), probe(ConditionResult::ofOthers({2})));
    EXPECT_FALSE(scene.test(disjoint, "a"));
}

TEST_F(LogicConditions, OrSkipsTheRightSideWhenTheLeftIsTrue) {
    const auto left = probe(ConditionResult::ofOthers({2}));
    const auto right = probe(ConditionResult::ofOthers({1, 3}));
    OrCondition c(left, right);
    const ConditionResult r = scene.test(c, "a");
    EXPECT_EQ(right->calls, 0);
    EXPECT_TRUE(r.isSet());
    EXPECT_EQ(r.others(), (Set{2}));  // a's result as it is, not the union
}

TEST_F(LogicConditions, OrEvaluatesTheRightSideWhenTheLeftIsFalse) {
    const auto right = probe(ConditionResult::ofOthers({1, 3}));
    OrCondition c(probe(false), right);
    const ConditionResult r = scene.test(c, "a");
    EXPECT_EQ(right->calls, 1);
    EXPECT_EQ(r.others(), (Set{1, 3}));

    OrCondition emptyThenTrue(probe(ConditionResult::ofOthers({})), probe(true));
    EXPECT_TRUE(scene.test(emptyThenTrue, "a"));
    OrCondition neither(probe(false), probe(ConditionResult::ofOthers({})));
    EXPECT_FALSE(scene.test(neither, "a"));
}

TEST_F(LogicConditions, ChildrenAreVisitedInOrder) {
    const auto left = probe(true);
    const auto right = probe(false);
    std::vector<Condition*> seen;
    AndCondition a(left, right);
    a.forEachChild([&](Condition& c) { seen.push_back(&c); });
    OrCondition o(right, left);
    o.forEachChild([&](Condition& c) { seen.push_back(&c); });
    EXPECT_EQ(seen, (std::vector<Condition*>{left.get(), right.get(), right.get(), left.get()}));
}

TEST_F(LogicConditions, NestedTreesShortCircuit) {
    // (false ∧ x) ∨ (true ∨ y): neither x nor y is evaluated.
    const auto x = probe(true);
    const auto y = probe(true);
    OrCondition tree(std::make_shared<AndCondition>(probe(false), x), std::make_shared<OrCondition>(probe(true), y));
    EXPECT_TRUE(scene.test(tree, "b"));
    EXPECT_EQ(x->calls, 0);
    EXPECT_EQ(y->calls, 0);
}

TEST(LogicConditionsConstruction, RejectsNullOperands) {
    EXPECT_THROW(AndCondition(nullptr, probe(true)), std::invalid_argument);
    EXPECT_THROW(OrCondition(probe(true), nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::storyboard::test
