#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "sbsim/radio/CounterRandom.h"
#include "sbsim/radio/Decibels.h"
#include "sbsim/radio/channel/ChannelSettings.h"
#include "sbsim/radio/channel/FrameErrorTable.h"
#include "sbsim/radio/propagation/FreeSpaceLoss.h"
#include "sbsim/radio/propagation/LogDistanceLoss.h"
#include "sbsim/radio/propagation/NakagamiFading.h"
#include "sbsim/radio/propagation/TwoRayGroundLoss.h"
#include "sbsim/radio/propagation/WinnerB1Loss.h"

namespace sbsim::radio {
namespace {

constexpr double kF = 5.89e9;

TEST(PathLoss, FreeSpaceIsFriis) {
    const FreeSpaceLoss fs(kF);
    // 20 log10(4π d f / c) written out: 100 m at 5.89 GHz is about 87.8 dB.
    const double expected = 20 * std::log10(4 * std::numbers::pi * 100 * kF / 299792458.0);
    EXPECT_NEAR(fs.lossDb(100), expected, 1e-9);
    EXPECT_NEAR(fs.lossDb(100), 87.85, 0.01);
    EXPECT_NEAR(fs.lossDb(1000) - fs.lossDb(100), 20.0, 1e-9);
}

TEST(PathLoss, LogDistanceFollowsItsExponent) {
    const LogDistanceLoss ld(47.86, 1, 2.7);
    EXPECT_NEAR(ld.lossDb(1), 47.86, 1e-12);
    EXPECT_NEAR(ld.lossDb(100), 47.86 + 54, 1e-9);
}

TEST(PathLoss, TwoRayGroundCrossesOverToFourthPower) {
    const TwoRayGroundLoss tr(kF, 1.5, 1.5);
    const double crossover = 4 * std::numbers::pi * 1.5 * 1.5 * kF / 299792458.0;
    EXPECT_NEAR(tr.crossoverDistance(), crossover, 1e-9);
    EXPECT_NEAR(tr.lossDb(100), FreeSpaceLoss(kF).lossDb(100), 1e-9);
    EXPECT_NEAR(tr.lossDb(1000), 40 * 3 - 20 * std::log10(2.25), 1e-9);
}

TEST(PathLoss, WinnerB1AtKnownDistancesAndItsBreakpoint) {
    const WinnerB1Loss w(kF, 1.5, 0.5);
    // d_BP = 4 · 1 · 1 · f / c ≈ 78.6 m.
    EXPECT_NEAR(w.breakpoint(), 4 * kF / 299792458.0, 1e-9);
    EXPECT_NEAR(w.breakpoint(), 78.6, 0.1);
    // At or above: 40 log10 d + 7.56 + 2.7 log10 5.89; at 300 m, 108.72 dB; at 100 m, 89.64 dB.
    EXPECT_NEAR(w.lossDb(300), 40 * std::log10(300.0) + 7.56 + 2.7 * std::log10(5.89), 1e-9);
    EXPECT_NEAR(w.lossDb(300), 108.72, 0.01);
    EXPECT_NEAR(w.lossDb(100), 89.64, 0.01);
    // Below the breakpoint the B1 law (22.7 log10 d + 27 + 20 log10 5.89, 80.97 dB at 50 m) is
    // under free space at 5.89 GHz, so free space holds there: 81.80 dB at 50 m, and up to the
    // crossing of free space with the far law, 81.1 m.
    EXPECT_LT(22.7 * std::log10(50.0) + 27 + 20 * std::log10(5.89), 81.0);
    EXPECT_NEAR(w.lossDb(50), 81.80, 0.01);
    EXPECT_NEAR(w.lossDb(w.breakpoint()), 20 * std::log10(w.breakpoint()) + 46.4 + 20 * std::log10(5.89 / 5), 1e-9);
    EXPECT_NEAR(w.lossDb(81.1), 40 * std::log10(81.1) + 7.56 + 2.7 * std::log10(5.89), 0.01);
    // Close by, free space is the floor: 20 log10 d + 46.4 + 20 log10(5.89/5).
    EXPECT_NEAR(w.lossDb(2), 20 * std::log10(2.0) + 46.4 + 20 * std::log10(5.89 / 5), 1e-9);
    EXPECT_GT(w.lossDb(2), 22.7 * std::log10(2.0) + 27 + 20 * std::log10(5.89));
}

TEST(FrameErrors, Goubet6MbpsInterpolatesInDb) {
    const FrameErrorTable t = FrameErrorTable::goubet6Mbps();
    EXPECT_DOUBLE_EQ(t.ferAtEbN0Db(-3), 1.0);
    EXPECT_DOUBLE_EQ(t.ferAtEbN0Db(5), 1.0);
    EXPECT_NEAR(t.ferAtEbN0Db(10), 0.4, 1e-12);
    EXPECT_NEAR(t.ferAtEbN0Db(15), 1.5e-2, 1e-12);
    // Halfway in dB between 10 and 15 dB: the geometric mean of the FERs.
    EXPECT_NEAR(t.ferAtEbN0Db(12.5), std::sqrt(0.4 * 1.5e-2), 1e-12);
    EXPECT_NEAR(t.ferAtEbN0Db(40), 1e-3, 1e-15);
    // Eb/N0 = SINR · B / R: at 6 Mbit/s over 10 MHz, 10 log10(10/6) ≈ 2.22 dB above the SINR.
    EXPECT_NEAR(t.fer(10 - 10 * std::log10(10.0 / 6.0), 10e6, 6e6), 0.4, 1e-12);
    EXPECT_THROW(FrameErrorTable({{5, 0.5}, {5, 0.1}}), std::invalid_argument);
    EXPECT_THROW(FrameErrorTable({{5, 0}}), std::invalid_argument);
}

TEST(Shadowing, NormalDrawsHaveUnitSpreadAndNoBias) {
    // One draw per (receiver) key, as the medium draws one per link and message.
    constexpr int n = 200000;
    double sum = 0, squares = 0;
    int beyondTwoSigma = 0;
    for (int k = 0; k < n; ++k) {
        CounterRandom r(7, 11, static_cast<std::uint64_t>(k / 100), static_cast<std::uint64_t>(k % 100),
                        DrawPurpose::Shadowing);
        const double x = 3.0 * r.normal();  // σ = 3 dB
        sum += x;
        squares += x * x;
        if (std::abs(x) > 6.0) ++beyondTwoSigma;
    }
    const double mean = sum / n;
    const double sd = std::sqrt(squares / n - mean * mean);
    EXPECT_NEAR(mean, 0.0, 0.03);
    EXPECT_NEAR(sd, 3.0, 0.03);
    EXPECT_NEAR(static_cast<double>(beyondTwoSigma) / n, 0.0455, 0.003);
}

TEST(Shadowing, ZigguratNormalHasTheMomentsAndTailsOfTheNormal) {
    // The medium draws one normal per link key; the ziggurat's rare paths (wedges, the tail
    // beyond 3.65) must give the exact distribution too, so the tails are checked as well as
    // the moments. Bounds: 5 standard errors of each estimate over n draws.
    constexpr int n = 10'000'000;
    double sum = 0, squares = 0, fourth = 0;
    std::int64_t beyond[5] = {0, 0, 0, 0, 0};  // |z| > 1, 2, 3, 4
    std::int64_t below = 0;                    // z < 0.5
    for (int k = 0; k < n; ++k) {
        CounterRandom r(29, 31, static_cast<std::uint64_t>(k / 1000), static_cast<std::uint64_t>(k % 1000),
                        DrawPurpose::Shadowing);
        const double z = r.normal();
        sum += z;
        squares += z * z;
        fourth += z * z * z * z;
        for (int s = 1; s <= 4; ++s) beyond[s] += std::abs(z) > s ? 1 : 0;
        below += z < 0.5 ? 1 : 0;
    }
    const double mean = sum / n;
    const double variance = squares / n - mean * mean;
    const auto share = [&](std::int64_t count) { return static_cast<double>(count) / n; };
    const auto bound = [&](double p) { return 5 * std::sqrt(p * (1 - p) / n); };
    // The normal's figures: P(|z| > s) = erfc(s / √2); P(z < 0.5) = Φ(0.5).
    const double published[5] = {0, 0.31731050786291415, 0.04550026389635842, 0.0026997960632601866,
                                 6.334248366623996e-05};
    std::printf("normal over %d draws: mean %.5f (0), variance %.5f (1), kurtosis %.4f (3), P(z<0.5) %.6f (%.6f)\n", n,
                mean, variance, fourth / n, share(below), 0.6914624612740131);
    for (int s = 1; s <= 4; ++s)
        std::printf("  P(|z|>%d) %.7f, the normal's %.7f\n", s, share(beyond[s]), published[s]);
    EXPECT_NEAR(mean, 0.0, 5 / std::sqrt(n));
    EXPECT_NEAR(variance, 1.0, 5 * std::sqrt(2.0 / n));
    EXPECT_NEAR(fourth / n, 3.0, 5 * std::sqrt(96.0 / n));
    EXPECT_NEAR(share(below), 0.6914624612740131, bound(0.6914624612740131));
    for (int s = 1; s <= 4; ++s) EXPECT_NEAR(share(beyond[s]), published[s], bound(published[s])) << "|z| > " << s;
}

TEST(Decibels, TableConversionMatchesPowAsExpDoes) {
    // Every hundredth of a dB from −250 to +80 dB. The error grows with |dB| (the rounding of
    // the argument y = dB · log2(10) / 10), as it does for std::exp(dB · ln 10 / 10).
    double worst = 0;
    double worstExp = 0;
    for (int c = -25000; c <= 8000; ++c) {
        const double db = c / 100.0 + 0.00123;
        const double exact = std::pow(10.0, db / 10);
        worst = std::max(worst, std::abs(dbToLinear(db) - exact) / exact);
        worstExp = std::max(worstExp, std::abs(std::exp(db * (std::numbers::ln10 / 10)) - exact) / exact);
    }
    std::printf("dB to linear, worst relative error against std::pow: %.2e (std::exp: %.2e)\n", worst, worstExp);
    EXPECT_LT(worst, 2e-14);
    EXPECT_EQ(dbToLinear(0), 1.0);
    EXPECT_NEAR(dbToLinear(30), 1000.0, 1e-12);
    EXPECT_NEAR(dbToLinear(-95), 3.1622776601683794e-10, 1e-24);
    EXPECT_EQ(dbToLinear(-1e9), 0.0);
    EXPECT_TRUE(std::isinf(dbToLinear(1e9)));
    EXPECT_NEAR(linearToDb(dbToLinear(-71.2)), -71.2, 1e-12);
}

TEST(Shadowing, DrawsArePureFunctionsOfTheirKey) {
    CounterRandom a(1, 2, 3, 4, DrawPurpose::Shadowing);
    CounterRandom b(1, 2, 3, 4, DrawPurpose::Shadowing);
    CounterRandom reverse(1, 4, 3, 2, DrawPurpose::Shadowing);
    CounterRandom other(1, 2, 3, 4, DrawPurpose::Decode);
    const double x = a.normal();
    EXPECT_EQ(x, b.normal());
    EXPECT_NE(x, reverse.normal());
    EXPECT_NE(CounterRandom(1, 2, 3, 4, DrawPurpose::Shadowing).uniform01(), other.uniform01());
}

TEST(Fading, NakagamiKeepsTheMeanPower) {
    for (const double m : {0.75, 1.5, 3.0}) {
        NakagamiFading fading;
        fading.m = m;
        constexpr int n = 100000;
        double sum = 0, squares = 0;
        for (int k = 0; k < n; ++k) {
            CounterRandom r(3, 5, static_cast<std::uint64_t>(k), 9, DrawPurpose::Fading);
            const double g = std::pow(10.0, fading.gainDb(100, r) / 10);
            sum += g;
            squares += g * g;
        }
        const double mean = sum / n;
        EXPECT_NEAR(mean, 1.0, 0.02) << "m = " << m;
        EXPECT_NEAR(squares / n - mean * mean, 1.0 / m, 0.05 / m) << "m = " << m;  // Gamma(m, 1/m)
    }
    NakagamiFading veins;
    veins.veinsDistanceRule = true;
    EXPECT_EQ(veins.shapeAt(79), 1.5);
    EXPECT_EQ(veins.shapeAt(81), 0.75);
}

TEST(Airtime, IsPreamblePlusFrameAtTheRate) {
    ChannelSettings s;
    // A 220-byte frame at 6 Mbit/s: 40 µs + 38 symbols of 8 µs (FrameSizeTest: the rounding).
    EXPECT_EQ(s.airtime(220).raw(), 40'000 + 304'000);
    s.rateMbps = 18;
    EXPECT_EQ(s.airtime(220).raw(), 40'000 + 104'000);
    EXPECT_EQ(s.aifs().raw(), 32'000 + 6 * 13'000);
}

}  // namespace
}  // namespace sbsim::radio
