#include <gtest/gtest.h>

#include "sbsim/radio/channel/DccStateMachine.h"

namespace sbsim::radio {
namespace {

using State = DccStateMachine::State;
using kernel::SimTime;

TEST(Dcc, StaysRelaxedOnALightChannel) {
    DccStateMachine dcc;
    for (int k = 0; k < 100; ++k) dcc.update(0.15);
    EXPECT_EQ(dcc.state(), State::Relaxed);
    EXPECT_EQ(dcc.transmissionInterval(), SimTime::fromMilliseconds(60));
}

TEST(Dcc, GoesActiveOnceTheWholeLastSecondIsLoaded) {
    DccStateMachine dcc;
    // Smoothed load 0.15, 0.225, 0.2625, …: the first sample (0.15 < 0.19) holds the state down
    // while it is among the last 10.
    for (int k = 0; k < 10; ++k) dcc.update(0.3);
    EXPECT_EQ(dcc.state(), State::Relaxed);
    dcc.update(0.3);
    EXPECT_EQ(dcc.state(), State::Active);
    // Loads near 0.3 are in Active 2's band (0.27–0.35): 180 ms.
    EXPECT_EQ(dcc.activeSubstate(), 1u);
    EXPECT_EQ(dcc.transmissionInterval(), SimTime::fromMilliseconds(180));
}

TEST(Dcc, RestrictiveAboveTheMaximumAndSlowToRelax) {
    DccStateMachine dcc;
    int samples = 0;
    while (dcc.state() != State::Restrictive && samples < 100) {
        dcc.update(0.8);
        ++samples;
    }
    ASSERT_EQ(dcc.state(), State::Restrictive);
    EXPECT_EQ(dcc.transmissionInterval(), SimTime::fromMilliseconds(460));
    // Going down looks at the largest load of the last 5 s: 50 samples of an idle channel.
    int down = 0;
    while (dcc.state() == State::Restrictive) {
        dcc.update(0.0);
        ++down;
    }
    EXPECT_EQ(dcc.state(), State::Active);
    EXPECT_GE(down, 45);
    EXPECT_LE(down, 50);
    while (dcc.state() != State::Relaxed) dcc.update(0.0);
    EXPECT_EQ(dcc.transmissionInterval(), SimTime::fromMilliseconds(60));
}

TEST(Dcc, ActiveSubstatesFollowTheLoadBands) {
    const struct {
        double load;
        int intervalMs;
    } cases[] = {{0.23, 100}, {0.31, 180}, {0.39, 260}, {0.47, 340}, {0.55, 420}};
    for (const auto& c : cases) {
        DccStateMachine dcc;
        for (int k = 0; k < 200; ++k) dcc.update(c.load);
        EXPECT_EQ(dcc.state(), State::Active) << c.load;
        EXPECT_EQ(dcc.transmissionInterval(), SimTime::fromMilliseconds(c.intervalMs)) << c.load;
    }
}

}  // namespace
}  // namespace sbsim::radio
