#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sbsim/radio/channel/LoadMonitor.h"

namespace sbsim::radio {
namespace {

using kernel::SimTime;

SimTime ms(int m) { return SimTime::fromMilliseconds(m); }

TEST(LoadMonitor, BusyTimeOverEachWindowIsTheRatioAndFeedsDcc) {
    LoadMonitor load;
    load.addStation(ms(0));
    load.addStation(ms(0));
    load.addStation(ms(0));
    load.setBusy(0, true, ms(10));
    load.setBusy(0, true, ms(20));  // no change: still busy since 10 ms
    load.setBusy(0, false, ms(40));
    load.setBusy(0, true, ms(80));  // busy across the window's end: 20 ms now, 30 ms in the next
    load.setBusy(1, true, ms(0));
    const std::vector<std::uint8_t> present{1, 1, 0};
    std::vector<LoadMonitor::Slot> changed;
    load.sample(ms(100), present, changed);
    EXPECT_DOUBLE_EQ(load.busyRatio(0), 0.5);
    EXPECT_DOUBLE_EQ(load.busyRatio(1), 1.0);
    EXPECT_DOUBLE_EQ(load.busyRatio(2), 0.0);  // absent: no sample
    ASSERT_TRUE(load.figures());
    EXPECT_EQ(load.figures()->samples, 2U);
    EXPECT_DOUBLE_EQ(load.figures()->meanCbr, 0.75);
    EXPECT_DOUBLE_EQ(load.figures()->maxCbr, 1.0);
    EXPECT_DOUBLE_EQ(load.dcc(0).smoothedLoad(), 0.25);  // ½ old (0) + ½ new

    load.setBusy(0, false, ms(130));
    load.sample(ms(200), present, changed);
    EXPECT_DOUBLE_EQ(load.busyRatio(0), 0.3);
    EXPECT_EQ(load.figures()->samples, 4U);
}

TEST(LoadMonitor, NoFiguresBeforeTheFirstSample) {
    LoadMonitor load;
    load.addStation(ms(0));
    EXPECT_FALSE(load.figures());
    std::vector<LoadMonitor::Slot> changed;
    load.sample(ms(0), {1}, changed);  // an empty window gives no ratio
    EXPECT_FALSE(load.figures());
}

TEST(LoadMonitor, ReportsTheStationsWhoseDccStateChanged) {
    // A station busy all the time: its smoothed load climbs past 0.19 (Active 1) once a whole
    // second of samples holds it there, and on to Restrictive; the idle one stays Relaxed.
    LoadMonitor load;
    load.addStation(ms(0));
    load.addStation(ms(0));
    load.setBusy(0, true, ms(0));
    const std::vector<std::uint8_t> present{1, 1};
    std::vector<LoadMonitor::Slot> changed;
    std::vector<std::string> states;
    for (int k = 1; k <= 30; ++k) {
        load.sample(ms(100 * k), present, changed);
        for (const LoadMonitor::Slot s : changed) {
            ASSERT_EQ(s, 0);
            states.emplace_back(load.dcc(s).name());
        }
    }
    ASSERT_FALSE(states.empty());
    EXPECT_EQ(states.back(), "restrictive");
    for (std::size_t k = 1; k < states.size(); ++k) EXPECT_NE(states[k], states[k - 1]) << "only changes";
    EXPECT_EQ(load.dcc(1).name(), "relaxed");
}

}  // namespace
}  // namespace sbsim::radio
