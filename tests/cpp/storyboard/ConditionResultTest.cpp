#include "sbsim/storyboard/ConditionResult.h"

#include <gtest/gtest.h>

namespace sbsim::storyboard {
namespace {

using Set = std::vector<VehicleIndex>;

TEST(ConditionResult, PlainValues) {
    EXPECT_TRUE(ConditionResult(true).isTrue());
    EXPECT_FALSE(ConditionResult(false).isTrue());
    EXPECT_FALSE(ConditionResult(true).isSet());
    EXPECT_TRUE(ConditionResult(true).others().empty());
    EXPECT_FALSE(static_cast<bool>(ConditionResult(false)));
}

TEST(ConditionResult, ASetIsTrueIffNonEmpty) {
    const ConditionResult empty = ConditionResult::ofOthers({});
    EXPECT_TRUE(empty.isSet());
    EXPECT_FALSE(empty.isTrue());
    const ConditionResult some = ConditionResult::ofOthers({2, 5});
    EXPECT_TRUE(some.isSet());
    EXPECT_TRUE(some.isTrue());
    EXPECT_EQ(some.others(), (Set{2, 5}));
}

TEST(ConditionResult, ConjunctionOfPlainValues) {
    using R = ConditionResult;
    EXPECT_TRUE(R::conjunction(true, true).isTrue());
    EXPECT_FALSE(R::conjunction(true, false).isTrue());
    EXPECT_FALSE(R::conjunction(false, true).isTrue());
    EXPECT_FALSE(R::conjunction(false, false).isTrue());
    EXPECT_FALSE(R::conjunction(true, true).isSet());
}

TEST(ConditionResult, ConjunctionKeepsASetWhenThePlainValueIsTrue) {
    using R = ConditionResult;
    const R set = R::ofOthers({1, 4});
    for (const R& r : {R::conjunction(set, true), R::conjunction(true, set)}) {
        EXPECT_TRUE(r.isSet());
        EXPECT_EQ(r.others(), (Set{1, 4}));
    }
    for (const R& r : {R::conjunction(set, false), R::conjunction(false, set)}) {
        EXPECT_FALSE(r.isTrue());
        EXPECT_FALSE(r.isSet());
        EXPECT_TRUE(r.others().empty());
    }
}

TEST(ConditionResult, ConjunctionOfSetsIsTheIntersection) {
    using R = ConditionResult;
    const R r = R::conjunction(R::ofOthers({1, 3, 5, 7}), R::ofOthers({0, 3, 4, 5, 8}));
    EXPECT_TRUE(r.isSet());
    EXPECT_EQ(r.others(), (Set{3, 5}));
    const R disjoint = R::conjunction(R::ofOthers({1, 2}), R::ofOthers({3}));
    EXPECT_TRUE(disjoint.isSet());
    EXPECT_FALSE(disjoint.isTrue());
}

TEST(ConditionResult, DisjunctionOfPlainValues) {
    using R = ConditionResult;
    EXPECT_TRUE(R::disjunction(true, false).isTrue());
    EXPECT_TRUE(R::disjunction(false, true).isTrue());
    EXPECT_TRUE(R::disjunction(true, true).isTrue());
    EXPECT_FALSE(R::disjunction(false, false).isTrue());
}

TEST(ConditionResult, DisjunctionPrefersANonEmptySetOverAPlainValue) {
    using R = ConditionResult;
    const R set = R::ofOthers({2, 9});
    for (const R& r : {R::disjunction(set, false), R::disjunction(false, set), R::disjunction(set, true),
                       R::disjunction(true, set)}) {
        EXPECT_TRUE(r.isSet());
        EXPECT_EQ(r.others(), (Set{2, 9}));
    }
    // An empty set yields to the plain value.
    const R empty = R::ofOthers({});
    EXPECT_TRUE(R::disjunction(empty, true).isTrue());
    EXPECT_FALSE(R::disjunction(empty, true).isSet());
    EXPECT_TRUE(R::disjunction(true, empty).isTrue());
    EXPECT_FALSE(R::disjunction(empty, false).isTrue());
}

TEST(ConditionResult, DisjunctionOfSetsIsTheUnion) {
    using R = ConditionResult;
    const R r = R::disjunction(R::ofOthers({1, 3, 5}), R::ofOthers({0, 3, 6}));
    EXPECT_TRUE(r.isSet());
    EXPECT_EQ(r.others(), (Set{0, 1, 3, 5, 6}));
    const R none = R::disjunction(R::ofOthers({}), R::ofOthers({}));
    EXPECT_TRUE(none.isSet());
    EXPECT_FALSE(none.isTrue());
}

}  // namespace
}  // namespace sbsim::storyboard
