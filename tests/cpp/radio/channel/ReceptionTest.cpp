#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "sbsim/radio/Decibels.h"
#include "sbsim/radio/channel/Reception.h"

namespace sbsim::radio {
namespace {

/// Keeps the carrier-sense changes reception reports, as the medium would act on them.
struct SenseLog : Reception::Listener {
    std::vector<std::pair<Reception::Slot, bool>> changes;
    void channelSensed(Reception::Slot s, bool busy) override { changes.emplace_back(s, busy); }
};

Link linkTo(Reception::Slot receiver, double dbm) {
    Link link;
    link.receiver = receiver;
    link.powerDbm = dbm;
    link.powerMw = dbToLinear(dbm);
    return link;
}

class ReceptionTest : public ::testing::Test {
protected:
    ReceptionTest() : reception(settings, log) {
        for (int k = 0; k < 3; ++k) reception.addStation();
    }
    ChannelSettings settings;  // sensing −85 dBm, noise −95 dBm, floor −105 dBm
    SenseLog log;
    Reception reception;
};

TEST_F(ReceptionTest, TheFirstFrameDetectedIsLockedAndTheSecondInterferes) {
    std::vector<Link> first{linkTo(1, -60)};
    std::vector<Link> second{linkTo(1, -70)};
    reception.startSending(0, 1);
    reception.frameStarts(1, first);
    EXPECT_TRUE(first[0].counted && first[0].locked);
    EXPECT_TRUE(reception.sensesBusy(1));
    ASSERT_EQ(log.changes.size(), 1U);
    EXPECT_EQ(log.changes[0], std::make_pair(Reception::Slot{1}, true));

    reception.startSending(2, 2);
    reception.frameStarts(2, second);
    EXPECT_FALSE(second[0].locked);
    EXPECT_NEAR(second[0].maxInterferenceMw, dbToLinear(-60), 1e-15);
    EXPECT_NEAR(first[0].maxInterferenceMw, dbToLinear(-70), 1e-15);
    EXPECT_EQ(log.changes.size(), 1U);  // busy already

    double sinrDb = 0;
    EXPECT_EQ(reception.decode(second[0], 7, 8, sinrDb), LossReason::Collision);
    // 10 dB over the interferer: Eb/N0 ≈ 12 dB at 6 Mbit/s, a FER of about 0.2; the draw decides,
    // and the SINR is the one the link had.
    (void)reception.decode(first[0], 7, 8, sinrDb);
    EXPECT_NEAR(sinrDb, linearToDb(dbToLinear(-60) / (dbToLinear(-95) + dbToLinear(-70))), 1e-12);

    const double left = reception.powerWithout(1, first);
    EXPECT_NEAR(left, dbToLinear(-70), 1e-15);
    reception.setSensedPower(1, left);
    reception.unlock(1, 1);
    EXPECT_TRUE(reception.sensesBusy(1));
    const double none = reception.powerWithout(1, second);
    EXPECT_EQ(none, 0.0);
    EXPECT_TRUE(reception.changesSense(1, none));
    reception.setSensedPower(1, none);
    EXPECT_FALSE(reception.sensesBusy(1));
    EXPECT_EQ(log.changes.back(), std::make_pair(Reception::Slot{1}, false));
}

TEST_F(ReceptionTest, ASenderLosesWhatItHearsAndFramesBelowTheFloorAreNotCounted) {
    std::vector<Link> frame{linkTo(1, -50), linkTo(2, -110)};
    reception.frameStarts(1, frame);
    EXPECT_TRUE(frame[0].counted);
    EXPECT_FALSE(frame[1].counted);  // below −105 dBm: no part of the sensed power
    EXPECT_FALSE(reception.sensesBusy(2));

    reception.startSending(1, 2);  // station 1 sends while receiving: half-duplex
    EXPECT_TRUE(frame[0].halfDuplex);
    EXPECT_TRUE(reception.sending(1));
    double sinrDb = 0;
    EXPECT_EQ(reception.decode(frame[0], 1, 2, sinrDb), LossReason::HalfDuplex);
    EXPECT_EQ(reception.decode(frame[1], 1, 3, sinrDb), LossReason::Sensing);
    reception.stopSending(1);
    EXPECT_FALSE(reception.sending(1));
}

TEST_F(ReceptionTest, AStrongLoneFrameIsDecoded) {
    std::vector<Link> frame{linkTo(1, -40)};
    reception.frameStarts(1, frame);
    double sinrDb = 0;
    // 55 dB of SNR, beyond the table's last point (a FER of 1e-3): at most a few of 200 frames lost.
    int lost = 0;
    for (std::uint64_t key = 0; key < 200; ++key) lost += reception.decode(frame[0], key, 9, sinrDb).has_value();
    EXPECT_LE(lost, 2);
    EXPECT_NEAR(sinrDb, 55.0, 1e-9);
}

}  // namespace
}  // namespace sbsim::radio
