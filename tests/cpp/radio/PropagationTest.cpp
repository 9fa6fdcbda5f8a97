#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sbsim/radio/ChannelSettings.h"
#include "sbsim/radio/CounterRandom.h"
#include "sbsim/radio/FrameErrorTable.h"
#include "sbsim/radio/FreeSpaceLoss.h"
#include "sbsim/radio/LogDistanceLoss.h"
#include "sbsim/radio/NakagamiFading.h"
#include "sbsim/radio/TwoRayGroundLoss.h"
#include "sbsim/radio/WinnerB1Loss.h"

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
    // 190 bytes at 6 Mbit/s: 40 µs + 220 · 8 / 6 µs = 333.33 µs.
    EXPECT_EQ(s.airtime(190).raw(), 40'000 + 293'334);
    s.rateMbps = 18;
    EXPECT_EQ(s.airtime(190).raw(), 40'000 + 97'778);
    EXPECT_EQ(s.aifs().raw(), 32'000 + 6 * 13'000);
}

}  // namespace
}  // namespace sbsim::radio
