#include "sbsim/kernel/RandomStream.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace sbsim::kernel {
namespace {

std::vector<double> draws(RandomStream& s, int n) {
    std::vector<double> out;
    for (int k = 0; k < n; ++k) out.push_back(s.uniform01());
    return out;
}

TEST(RandomStream, SameSeedAndIndexGiveTheSameSequence) {
    RandomStream a(42, 3);
    RandomStream b(42, 3);
    EXPECT_EQ(draws(a, 100), draws(b, 100));
}

TEST(RandomStream, IndicesAndSeedsGiveDifferentSequences) {
    RandomStream base(42, 0);
    RandomStream otherIndex(42, 1);
    RandomStream otherSeed(43, 0);
    RandomStream highBits(42 + (std::uint64_t{1} << 32), 0);  // seed_seq alone would drop these bits
    const std::vector<double> reference = draws(base, 20);
    EXPECT_NE(draws(otherIndex, 20), reference);
    EXPECT_NE(draws(otherSeed, 20), reference);
    EXPECT_NE(draws(highBits, 20), reference);
}

TEST(RandomStream, IsPortable) {
    // mt19937_64 and seed_seq are fully specified, so this holds on every standard library.
    RandomStream s(1, 0);
    std::seed_seq seq{1u, 0u, 0u};
    std::mt19937_64 engine(seq);
    for (int k = 0; k < 5; ++k) EXPECT_EQ(s.uniform01(), static_cast<double>(engine() >> 11) / 9007199254740992.0);
}

TEST(RandomStream, Uniform01HasFiftyThreeBitsInTheUnitInterval) {
    RandomStream s(5, 0);
    double sum = 0;
    bool usesLowBits = false;
    constexpr int n = 100'000;
    for (int k = 0; k < n; ++k) {
        const double u = s.uniform01();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        const double scaled = u * 9007199254740992.0;  // 2^53
        ASSERT_EQ(scaled, std::floor(scaled));
        usesLowBits |= std::fmod(scaled, 2.0) == 1.0;
        sum += u;
    }
    EXPECT_TRUE(usesLowBits);
    EXPECT_NEAR(sum / n, 0.5, 0.01);
}

TEST(RandomStream, UniformIsWithinBounds) {
    RandomStream s(8, 2);
    for (int k = 0; k < 10'000; ++k) {
        const double u = s.uniform(-3, 7);
        ASSERT_GE(u, -3.0);
        ASSERT_LT(u, 7.0);
    }
    EXPECT_EQ(s.uniform(4, 4), 4.0);
}

}  // namespace
}  // namespace sbsim::kernel
