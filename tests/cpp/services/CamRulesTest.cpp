// EN 302 637-2's CAM generation rules on synthetic trajectories, checked every 100 ms as the
// middleware does: a slow straight car sends every T_GenCamMax (1 s); a fast one on the 4 m rule,
// and after it stops, three more at the last dynamics interval before 1 s again; a turning car on
// the 4° rule (also across 0°/360°); an accelerating car on the 0.5 m/s rule; DCC holding the
// interval; the fixed-rate option.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "sbsim/services/ca/CamGenerationRules.h"

namespace sbsim::services {
namespace {

using kernel::SimTime;
using Reason = CamGenerationRules::Reason;

struct Send {
    double t;
    Reason reason;
};

/// Checks the rules every 100 ms from 0 to `end` s with the station at `at(t)`.
std::vector<Send> drive(CamGenerationRules& rules, double end, const std::function<CamDynamics(double)>& at,
                        std::optional<SimTime> dcc = std::nullopt) {
    std::vector<Send> sends;
    for (int k = 0; k <= static_cast<int>(end * 10 + 0.5); ++k) {
        const double t = k / 10.0;
        const Reason r = rules.check(SimTime::fromMilliseconds(100 * k), at(t), dcc);
        if (r != Reason::None) sends.push_back({t, r});
    }
    return sends;
}

std::vector<double> intervals(const std::vector<Send>& sends, double from = 0) {
    std::vector<double> out;
    for (std::size_t i = 1; i < sends.size(); ++i) {
        if (sends[i - 1].t >= from - 1e-9) out.push_back(std::round((sends[i].t - sends[i - 1].t) * 10) / 10);
    }
    return out;
}

TEST(CamRules, SlowStraightCarSendsEverySecond) {
    CamGenerationRules rules;
    // 3 m/s: 3 m in a second, under the 4 m rule.
    const auto sends = drive(rules, 10, [](double t) { return CamDynamics{{3 * t, 0}, 3, 90}; });
    ASSERT_EQ(sends.front().reason, Reason::First);
    EXPECT_EQ(intervals(sends), std::vector<double>(10, 1.0));
    for (std::size_t i = 1; i < sends.size(); ++i) EXPECT_EQ(sends[i].reason, Reason::Timeout);
}

TEST(CamRules, FastCarSendsOnThePositionRuleThenThreeAtThatIntervalAfterStopping) {
    CamGenerationRules rules;
    // 19 m/s until 5.05 s (3.8 m after 0.2 s, 5.7 m after 0.3 s: every 0.3 s), then standing.
    const auto at = [](double t) {
        return t < 5.05 ? CamDynamics{{19 * t, 0}, 19, 90} : CamDynamics{{19 * 5.05, 0}, 0, 90};
    };
    const auto sends = drive(rules, 12, at);
    std::vector<double> moving;
    for (std::size_t i = 1; i < sends.size() && sends[i].t < 5; ++i) {
        moving.push_back(std::round((sends[i].t - sends[i - 1].t) * 10) / 10);
        EXPECT_EQ(sends[i].reason, Reason::Dynamics);
    }
    EXPECT_EQ(moving, std::vector<double>(moving.size(), 0.3));
    EXPECT_EQ(rules.genCam(), SimTime::fromSeconds(1));  // back at Max after standing for a while
    // After the stop (speed and position changed: one more dynamics CAM), T_GenCam is the last
    // dynamics interval for three CAMs, then 1 s.
    const auto after = intervals(sends, 5.0);
    ASSERT_GE(after.size(), 6u);
    EXPECT_EQ(std::vector<double>(after.begin(), after.begin() + 4), (std::vector<double>{0.3, 0.3, 0.3, 1.0}));
    EXPECT_EQ(after[4], 1.0);
}

TEST(CamRules, TurningCarSendsOnTheHeadingRule) {
    CamGenerationRules rules;
    // Standing still, turning 19°/s: 3.8° after 0.2 s, 5.7° after 0.3 s.
    const auto sends = drive(rules, 5, [](double t) { return CamDynamics{{0, 0}, 0.0, 19 * t}; });
    const auto iv = intervals(sends);
    EXPECT_EQ(iv, std::vector<double>(iv.size(), 0.3));
    EXPECT_GE(iv.size(), 15u);
}

TEST(CamRules, HeadingIsComparedAcrossNorth) {
    EXPECT_DOUBLE_EQ(CamGenerationRules::headingDifference(359, 1), 2);
    EXPECT_DOUBLE_EQ(CamGenerationRules::headingDifference(1, 359), 2);
    EXPECT_DOUBLE_EQ(CamGenerationRules::headingDifference(10, 190), 180);
    EXPECT_DOUBLE_EQ(CamGenerationRules::headingDifference(720 + 3, 358), 5);
    // Turning 9°/s through north (355° → 2°): a CAM every 0.5 s (4.5° > 4°), never on a
    // wrap-around jump of ~358°.
    CamGenerationRules rules;
    const auto sends = drive(rules, 3, [](double t) {
        return CamDynamics{{0, 0}, 0, std::fmod(355.0 + 9 * t, 360.0)};
    });
    const auto iv = intervals(sends);
    EXPECT_EQ(iv, std::vector<double>(iv.size(), 0.5));
}

TEST(CamRules, AcceleratingCarSendsOnTheSpeedRule) {
    CamGenerationRules rules;
    // 2 m/s² from standing: the speed changes by 0.6 m/s in 0.3 s (> 0.5) while it moves < 4 m.
    const auto sends = drive(rules, 3, [](double t) { return CamDynamics{{t * t, 0}, 2 * t, 90}; });
    const auto iv = intervals(sends);
    EXPECT_EQ(iv, std::vector<double>(iv.size(), 0.3));
    for (std::size_t i = 1; i < sends.size(); ++i) EXPECT_EQ(sends[i].reason, Reason::Dynamics);
}

TEST(CamRules, DccHoldsTheInterval) {
    const auto fast = [](double t) { return CamDynamics{{19 * t, 0}, 19, 90}; };
    CamGenerationRules held;
    EXPECT_EQ(intervals(drive(held, 5, fast, SimTime::fromMilliseconds(500))), std::vector<double>(10, 0.5));
    // DCC beyond T_GenCamMax is clamped to it; below T_GenCamMin to that.
    CamGenerationRules slow;
    EXPECT_EQ(intervals(drive(slow, 5, fast, SimTime::fromSeconds(2))), std::vector<double>(5, 1.0));
    CamGenerationRules quick;
    EXPECT_EQ(quick.genCamDcc(SimTime::fromMilliseconds(20)), SimTime::fromMilliseconds(100));
}

TEST(CamRules, FixedRateSendsEveryGenCamDcc) {
    CamRuleSettings settings;
    settings.fixedRate = true;
    CamGenerationRules rules(settings);
    const auto standing = [](double) { return CamDynamics{}; };
    EXPECT_EQ(intervals(drive(rules, 1, standing)), std::vector<double>(10, 0.1));
    CamGenerationRules dcc(settings);
    // 250 ms on the 100 ms check grid: every 0.3 s.
    EXPECT_EQ(intervals(drive(dcc, 3, standing, SimTime::fromMilliseconds(250))), std::vector<double>(10, 0.3));
}

}  // namespace
}  // namespace sbsim::services
