#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "sbsim/radio/CounterRandom.h"
#include "sbsim/radio/propagation/CorrelatedShadowing.h"
#include "sbsim/radio/propagation/ThreeGppHighwayLoss.h"
#include "sbsim/radio/propagation/ThreeGppUrbanLoss.h"

namespace sbsim::radio {
namespace {

using kernel::SimTime;

/// `pairs` pairs, station a of each moving `step` m along x per update and b standing; their values
/// over `updates` updates, in units of σ.
std::vector<std::vector<double>> walks(int pairs, int updates, double step, double dCorr, std::uint64_t seed) {
    CorrelatedShadowing shadowing(1.0, dCorr, seed);
    std::vector<std::vector<double>> z(static_cast<std::size_t>(pairs));
    for (int t = 0; t < updates; ++t) {
        const SimTime now = SimTime::fromMilliseconds(100 * t);
        for (int p = 0; p < pairs; ++p) {
            const std::uint64_t a = CounterRandom::keyOf("a" + std::to_string(p));
            const std::uint64_t b = CounterRandom::keyOf("b" + std::to_string(p));
            const auto pair = shadowing.pair(a, b, now);
            z[static_cast<std::size_t>(p)].push_back(shadowing.valueDb(pair, a, step * t, 0, b, 500, 0));
        }
    }
    return z;
}

TEST(CorrelatedShadowing, AutocorrelationFallsAsExpOfTheDistanceMoved) {
    const double dCorr = 10;
    const double step = 2;  // m per update
    const auto z = walks(400, 250, step, dCorr, 7);
    double sum = 0, squares = 0, n = 0;
    for (const auto& w : z) {
        for (const double v : w) {
            sum += v;
            squares += v * v;
            ++n;
        }
    }
    const double mean = sum / n;
    const double variance = squares / n - mean * mean;
    EXPECT_NEAR(mean, 0, 0.03);
    EXPECT_NEAR(variance, 1, 0.05);  // stays log-normal with σ, whatever the moves
    for (const int lag : {1, 3, 5, 10}) {
        double c = 0, m = 0;
        for (const auto& w : z) {
            for (std::size_t t = 0; t + static_cast<std::size_t>(lag) < w.size(); ++t) {
                c += (w[t] - mean) * (w[t + static_cast<std::size_t>(lag)] - mean);
                ++m;
            }
        }
        const double expected = std::exp(-step * lag / dCorr);
        EXPECT_NEAR(c / m / variance, expected, 0.03) << "lag " << lag * step << " m";
    }
}

TEST(CorrelatedShadowing, BothDirectionsSeeOneValue) {
    CorrelatedShadowing ab(3, 10, 1), ba(3, 10, 1);
    const std::uint64_t a = CounterRandom::keyOf("a"), b = CounterRandom::keyOf("b");
    for (int t = 0; t < 50; ++t) {
        const SimTime now = SimTime::fromMilliseconds(100 * t);
        const double ax = 1.5 * t, bx = 200 - 0.7 * t;
        const double one = ab.valueDb(ab.pair(a, b, now), a, ax, 0, b, bx, 1);
        const double other = ba.valueDb(ba.pair(b, a, now), b, bx, 1, a, ax, 0);
        EXPECT_EQ(one, other);
    }
}

TEST(CorrelatedShadowing, ValuesAreAFunctionOfSeedPairAndMovesAlone) {
    const auto once = walks(20, 30, 1, 10, 5);
    EXPECT_EQ(walks(20, 30, 1, 10, 5), once);
    EXPECT_NE(walks(20, 30, 1, 10, 6), once);
    // A pair that does not move keeps its value.
    CorrelatedShadowing still(3, 10, 5);
    const auto p = still.pair(1, 2, SimTime::zero());
    const double first = still.valueDb(p, 1, 0, 0, 2, 100, 0);
    EXPECT_NE(first, 0);
    EXPECT_EQ(still.valueDb(still.pair(1, 2, SimTime::fromMilliseconds(500)), 1, 0, 0, 2, 100, 0), first);
}

TEST(CorrelatedShadowing, PairsUnseenForFiveSecondsAreForgotten) {
    CorrelatedShadowing shadowing(3, 10, 5);
    for (std::uint64_t k = 1; k <= 100; ++k) shadowing.valueDb(shadowing.pair(0, k, SimTime::zero()), 0, 0, 0, k, 0, 0);
    shadowing.valueDb(shadowing.pair(0, 1, SimTime::fromMilliseconds(4'000)), 0, 0, 0, 1, 0, 0);
    shadowing.forget(SimTime::fromMilliseconds(4'000));
    EXPECT_EQ(shadowing.pairs(), 100u);  // nobody unseen for 5 s yet
    shadowing.forget(SimTime::fromMilliseconds(6'000));
    EXPECT_EQ(shadowing.pairs(), 1u);  // only the pair seen at 4 s
    // Seen again, a forgotten pair starts afresh: its value is its first draw again, not a continuation.
    CorrelatedShadowing fresh(3, 10, 5);
    const double first = fresh.valueDb(fresh.pair(0, 2, SimTime::zero()), 0, 0, 0, 2, 0, 0);
    EXPECT_EQ(shadowing.valueDb(shadowing.pair(0, 2, SimTime::fromMilliseconds(6'100)), 0, 50, 0, 2, 0, 0), first);
}

TEST(CorrelatedShadowing, ARecordASweepFreedServesANewPairAsAFreshOne) {
    // A record holds no key (the callers' a and b name the pair): reused for another pair, that
    // pair's values are its own, in either direction, as in a table that never held the old one.
    CorrelatedShadowing reused(3, 10, 5), fresh(3, 10, 5);
    for (std::uint64_t k = 1; k <= 20; ++k) reused.valueDb(reused.pair(0, k, SimTime::zero()), 0, 0, 0, k, 9, 0);
    reused.forget(SimTime::fromMilliseconds(6'000));
    ASSERT_EQ(reused.pairs(), 0u);
    const std::uint64_t a = CounterRandom::keyOf("x"), b = CounterRandom::keyOf("y");
    for (int t = 0; t < 10; ++t) {
        const SimTime now = SimTime::fromMilliseconds(6'000 + 100 * t);
        const double one = reused.valueDb(reused.pair(b, a, now), b, 0, 1, a, 2.0 * t, 0);
        EXPECT_EQ(one, fresh.valueDb(fresh.pair(a, b, now), a, 2.0 * t, 0, b, 0, 1));
    }
}

TEST(ThreeGppLoss, TheTablesLaws) {
    const double f = 5.9e9;
    const ThreeGppHighwayLoss highway(f);
    EXPECT_NEAR(highway.lossDb(100), 32.4 + 40 + 20 * std::log10(5.9), 1e-9);
    EXPECT_NEAR(highway.lossDb(1000) - highway.lossDb(100), 20, 1e-9);
    const ThreeGppUrbanLoss los(f, true), nlos(f, false);
    EXPECT_NEAR(los.lossDb(100), 38.77 + 33.4 + 18.2 * std::log10(5.9), 1e-9);
    EXPECT_NEAR(nlos.lossDb(100), 36.85 + 60 + 18.9 * std::log10(5.9), 1e-9);
    EXPECT_GT(nlos.lossDb(50), los.lossDb(50));
    EXPECT_EQ(los.lossDb(0.2), los.lossDb(1));  // below 1 m taken as 1 m
    EXPECT_THROW(ThreeGppHighwayLoss(0), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::radio
