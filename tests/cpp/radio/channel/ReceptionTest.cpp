#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/Decibels.h"
#include "sbsim/radio/channel/ChannelStations.h"
#include "sbsim/radio/channel/FarCells.h"
#include "sbsim/radio/channel/Reception.h"

namespace sbsim::radio {
namespace {

/// Keeps the carrier-sense changes reception reports, as the medium would act on them.
struct SenseLog : Reception::Listener {
    std::vector<std::pair<Reception::Slot, bool>> changes;
    void channelSensed(Reception::Slot s, bool busy) override { changes.emplace_back(s, busy); }
};

using kernel::SimTime;

Link linkTo(Reception::Slot receiver, double dbm) {
    Link link;
    link.receiver = receiver;
    link.powerDbm = dbm;
    link.powerMw = dbToLinear(dbm);
    return link;
}

/// A step whose links are all drawn (their Link in the frame's vector).
StepLinks allDrawn(const std::vector<Link>& links) {
    StepLinks step;
    for (const Link& link : links) {
        step.receivers.push_back(link.receiver);
        step.bin.push_back(0);
        step.distance.push_back(link.distance);
        step.tier.push_back(StepLinks::kDrawn);
        step.units.push_back(0);
    }
    return step;
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
    reception.startSending(0, 1, SimTime::zero());
    reception.frameStarts(1, allDrawn(first), first);
    EXPECT_TRUE(first[0].counted && first[0].locked);
    EXPECT_TRUE(reception.sensesBusy(1));
    ASSERT_EQ(log.changes.size(), 1U);
    EXPECT_EQ(log.changes[0], std::make_pair(Reception::Slot{1}, true));

    reception.startSending(2, 2, SimTime::zero());
    reception.frameStarts(2, allDrawn(second), second);
    EXPECT_FALSE(second[0].locked);
    EXPECT_NEAR(first[0].maxInterferenceMw, dbToLinear(-70), 1e-15);  // only the decoded frame's is kept
    EXPECT_EQ(log.changes.size(), 1U);                                // busy already

    double sinrDb = 0;
    EXPECT_EQ(reception.decode(second[0], 7, 8, sinrDb), LossReason::Collision);
    // 10 dB over the interferer: Eb/N0 ≈ 12 dB at 6 Mbit/s, a FER of about 0.2; the draw decides,
    // and the SINR is the one the link had.
    (void)reception.decode(first[0], 7, 8, sinrDb);
    // (Within 1e-9 dB: the heard power is summed in units of 2^-64 mW.)
    EXPECT_NEAR(sinrDb, linearToDb(dbToLinear(-60) / (dbToLinear(-95) + dbToLinear(-70))), 1e-9);

    const double left = reception.frameEnds(1, SimTime::zero(), first[0]);
    EXPECT_NEAR(left, dbToLinear(-70), 1e-15);
    reception.setSensedPower(1, left);
    EXPECT_TRUE(reception.sensesBusy(1));
    const double none = reception.frameEnds(2, SimTime::zero(), second[0]);
    EXPECT_EQ(none, 0.0);  // the fixed-point sum returns to exactly nothing
    EXPECT_TRUE(reception.changesSense(1, none));
    reception.setSensedPower(1, none);
    EXPECT_FALSE(reception.sensesBusy(1));
    EXPECT_EQ(log.changes.back(), std::make_pair(Reception::Slot{1}, false));
}

TEST_F(ReceptionTest, ASenderLosesWhatItHearsAndFramesBelowTheFloorAreNotCounted) {
    std::vector<Link> frame{linkTo(1, -50), linkTo(2, -110)};
    reception.frameStarts(1, allDrawn(frame), frame);
    EXPECT_TRUE(frame[0].counted);
    EXPECT_FALSE(frame[1].counted);  // below −105 dBm: no part of the sensed power
    EXPECT_FALSE(reception.sensesBusy(2));

    reception.startSending(1, 2, SimTime::fromMilliseconds(1));  // station 1 sends while receiving
    reception.frameEnds(1, SimTime::zero(), frame[0]);
    reception.frameEnds(1, SimTime::zero(), frame[1]);
    EXPECT_TRUE(frame[0].halfDuplex);
    EXPECT_FALSE(frame[1].halfDuplex);  // not counted: lost below the sensing threshold
    EXPECT_TRUE(reception.sending(1));
    double sinrDb = 0;
    EXPECT_EQ(reception.decode(frame[0], 1, 2, sinrDb), LossReason::HalfDuplex);
    EXPECT_EQ(reception.decode(frame[1], 1, 3, sinrDb), LossReason::Sensing);
    reception.stopSending(1);
    EXPECT_FALSE(reception.sending(1));
}

TEST_F(ReceptionTest, ASendingThatEndedBeforeTheFrameStartedCostsNothing) {
    reception.startSending(1, 5, SimTime::zero());
    reception.stopSending(1);
    std::vector<Link> frame{linkTo(1, -50)};
    reception.frameStarts(1, allDrawn(frame), frame);
    reception.frameEnds(1, SimTime::fromMilliseconds(2), frame[0]);
    EXPECT_FALSE(frame[0].halfDuplex);
    EXPECT_TRUE(frame[0].locked);
}

TEST_F(ReceptionTest, TheHeardPowerIsExactWhateverTheOrderFramesLeave) {
    // Powers thirteen orders of magnitude apart: a floating sum that adds and subtracts drifts,
    // the fixed-point one returns to exactly zero.
    std::vector<Link> frames[4] = {{linkTo(1, -30)}, {linkTo(1, -104)}, {linkTo(1, -61.7)}, {linkTo(1, -99.3)}};
    for (std::uint64_t k = 0; k < 4; ++k) reception.frameStarts(k + 1, allDrawn(frames[k]), frames[k]);
    EXPECT_NEAR(reception.frameEnds(1, SimTime::zero(), frames[0][0]),
                dbToLinear(-104) + dbToLinear(-61.7) + dbToLinear(-99.3), 1e-18);
    reception.frameEnds(3, SimTime::zero(), frames[2][0]);
    EXPECT_NEAR(reception.frameEnds(2, SimTime::zero(), frames[1][0]), dbToLinear(-99.3), 1e-18);
    EXPECT_EQ(reception.frameEnds(4, SimTime::zero(), frames[3][0]), 0.0);
}

TEST_F(ReceptionTest, AnInterferenceOnlyLinkAddsItsPowerButIsNeverDetected) {
    std::vector<Link> first{linkTo(1, -60)};
    reception.frameStarts(1, allDrawn(first), first);
    // A second frame reaching station 1 only as interference (−90 dBm, below sensing), and
    // station 2 as well, which it leaves idle.
    StepLinks quiet;
    for (const Reception::Slot r : {1, 2}) {
        quiet.receivers.push_back(r);
        quiet.bin.push_back(0);
        quiet.distance.push_back(500);
        quiet.tier.push_back(StepLinks::kInterference);
        quiet.units.push_back(Reception::unitsOf(dbToLinear(-90)));
    }
    std::vector<Link> none;
    std::vector<std::uint32_t> half;
    reception.frameStarts(2, quiet, none, &half);
    EXPECT_NEAR(first[0].maxInterferenceMw, dbToLinear(-90), 1e-18);
    EXPECT_FALSE(reception.sensesBusy(2));
    EXPECT_TRUE(half.empty());
    EXPECT_EQ(reception.leave(2, quiet.units[1]), 0.0);
    EXPECT_NEAR(reception.leave(1, quiet.units[0]), dbToLinear(-60), 1e-15);
}

/// A step of one sender whose only links are whole far cells (ChannelSettings::farCellM).
StepLinks farCells(std::vector<std::pair<std::int32_t, double>> cells) {
    StepLinks step;
    for (const auto& [cell, dbm] : cells) {
        step.farCell.push_back(cell);
        step.farUnits.push_back(Reception::unitsOf(dbToLinear(dbm)));
        step.farOccupants.push_back(1);
        step.farBin.push_back(12);
    }
    return step;
}

TEST_F(ReceptionTest, AFarCellsFieldInterferesWithTheFrameItsStationsDecodeAndIsSensed) {
    // Stations 0, 1 and 2 stand in one 100 m cell, far cell 0.
    ChannelStations stations;
    for (const char* id : {"a", "b", "c"}) {
        const auto s = stations.add(id, 0);
        stations.x[s] = 10.0 + s;
        stations.y[s] = 20.0;
        stations.present[s] = 1;
    }
    FarCells cells(100);
    cells.newStep(stations);
    ASSERT_EQ(cells.cellOf(2), 0);
    reception.moveStations(cells);
    // Station 1 decodes a frame; station 2 listens idle.
    std::vector<Link> decoded{linkTo(1, -60)};
    decoded[0].cell = 0;
    reception.frameStarts(1, allDrawn(decoded), decoded);
    ASSERT_TRUE(decoded[0].locked);
    log.changes.clear();
    // A far frame's field rises in cell 0 and falls again before the decoded frame ends: the
    // largest interference is that field, found in the cell's log at the end. Below the sensing
    // threshold, no station's carrier sense changes.
    const StepLinks far = farCells({{0, -92}, {3, -80}});
    std::vector<Link> none;
    reception.frameStarts(2, far, none);
    EXPECT_NEAR(reception.farFieldMw(0), dbToLinear(-92), 1e-18);
    EXPECT_TRUE(log.changes.empty());
    // Another far frame raises the field above it (−92 and −86.5 dBm): stations 0 and 2 sense it
    // busy, and idle again when it ends.
    const StepLinks loud = farCells({{0, -85.9}});
    reception.frameStarts(3, loud, none);
    const std::vector<std::pair<Reception::Slot, bool>> busy{{0, true}, {2, true}};
    EXPECT_EQ(log.changes, busy);
    reception.farEnds(loud);
    reception.farEnds(far);
    const std::vector<std::pair<Reception::Slot, bool>> idle{{0, true}, {2, true}, {0, false}, {2, false}};
    EXPECT_EQ(log.changes, idle);
    EXPECT_EQ(reception.farFieldMw(0), 0.0);
    EXPECT_EQ(reception.farFieldMw(3), 0.0);
    reception.frameEnds(1, SimTime::zero(), decoded[0]);
    EXPECT_NEAR(decoded[0].maxInterferenceMw, dbToLinear(-92) + dbToLinear(-85.9), 1e-18);
    EXPECT_EQ(reception.logOverflows(), 0u);
}

TEST_F(ReceptionTest, ADecodingStationsInterferenceIsTheLargestSumOfItsLinksAndItsCellsField) {
    // Stations 1 and 2 decode a frame each, in far cells 0 and 1.
    std::vector<Link> first{linkTo(1, -60)}, second{linkTo(2, -60)};
    first[0].cell = 0;
    second[0].cell = 1;
    reception.frameStarts(1, allDrawn(first), first);
    reception.frameStarts(2, allDrawn(second), second);
    const auto own = [](Reception::Slot r) {
        StepLinks near;
        near.receivers.push_back(r);
        near.bin.push_back(0);
        near.distance.push_back(300);
        near.tier.push_back(StepLinks::kInterference);
        near.units.push_back(Reception::unitsOf(dbToLinear(-90)));
        return near;
    };
    std::vector<Link> none;
    // At station 1 a link of its own (−90 dBm) comes and goes, then the field rises (−96 dBm)
    // twice: the largest sum is the link alone, not the link and the field together.
    const StepLinks near1 = own(1);
    reception.frameStarts(3, near1, none);
    reception.leave(1, near1.units[0]);
    const StepLinks far = farCells({{0, -96}, {1, -96}});
    reception.frameStarts(4, far, none);
    // At station 2 the link comes while the field is up: their sum.
    const StepLinks near2 = own(2);
    reception.frameStarts(5, near2, none);
    reception.leave(2, near2.units[0]);
    reception.frameStarts(6, farCells({{0, -96}}), none);
    reception.frameEnds(1, SimTime::zero(), first[0]);
    reception.frameEnds(2, SimTime::zero(), second[0]);
    EXPECT_NEAR(first[0].maxInterferenceMw, dbToLinear(-90), 1e-18);
    EXPECT_NEAR(second[0].maxInterferenceMw, dbToLinear(-90) + dbToLinear(-96), 1e-18);
    // A field that rises after the frame ended is no part of it.
    reception.frameStarts(7, farCells({{0, -80}}), none);
    EXPECT_NEAR(first[0].maxInterferenceMw, dbToLinear(-90), 1e-18);
}

TEST_F(ReceptionTest, AStrongLoneFrameIsDecoded) {
    std::vector<Link> frame{linkTo(1, -40)};
    reception.frameStarts(1, allDrawn(frame), frame);
    double sinrDb = 0;
    // 55 dB of SNR, beyond the table's last point (a FER of 1e-3): at most a few of 200 frames lost.
    int lost = 0;
    for (std::uint64_t key = 0; key < 200; ++key) lost += reception.decode(frame[0], key, 9, sinrDb).has_value();
    EXPECT_LE(lost, 2);
    EXPECT_NEAR(sinrDb, 55.0, 1e-9);
}

TEST_F(ReceptionTest, ManyStationsKeepTheirOwnStateThroughOverlappingFrames) {
    // Each station's record (its power, sending, decoding, sense) against a model kept here, over
    // thousands of overlapping frames among 300 stations: a record shared, misplaced or with two
    // fields crossed shows as a wrong flag, sense or power.
    constexpr int kStations = 300;
    for (int k = 3; k < kStations; ++k) reception.addStation();
    using Units = Reception::Units;
    struct Model {
        Units heard = 0;
        Reception::FrameId sending = 0, locked = 0;
        SimTime sendStart = SimTime::fromNanoseconds(-1);
    };
    std::vector<Model> model(kStations);
    struct Frame {
        Reception::FrameId id;
        Reception::Slot sender;
        SimTime start;
        std::vector<Link> links;
    };
    std::vector<std::unique_ptr<Frame>> onAir;
    const double sensingMw = dbToLinear(settings.sensingDbm);
    const double floorMw = dbToLinear(settings.interferenceFloorDbm);
    const auto mwOf = [](Units u) { return static_cast<double>(u) / 18446744073709551616.0; };
    std::mt19937_64 random(28);
    std::uniform_int_distribution<int> station(0, kStations - 1);
    std::uniform_real_distribution<double> dbm(-112, -55);
    Reception::FrameId nextId = 1;
    std::size_t locks = 0, halves = 0, ends = 0;
    for (int op = 0; op < 6000; ++op) {
        const SimTime now = SimTime::fromNanoseconds(1000 * op);
        if (onAir.empty() || random() % 2 == 0) {
            const Reception::Slot s = station(random);
            if (model[s].sending != 0) continue;
            auto frame = std::make_unique<Frame>(Frame{nextId++, s, now, {}});
            const int receivers = static_cast<int>(random() % 24);
            std::vector<char> taken(kStations, 0);
            taken[s] = 1;
            for (int k = 0; k < receivers; ++k) {
                const Reception::Slot r = station(random);
                if (taken[r]) continue;
                taken[r] = 1;
                frame->links.push_back(linkTo(r, dbm(random)));
            }
            reception.startSending(s, frame->id, now);
            model[s] = {model[s].heard, frame->id, 0, now};
            reception.frameStarts(frame->id, allDrawn(frame->links), frame->links);
            for (const Link& link : frame->links) {
                Model& m = model[link.receiver];
                EXPECT_EQ(link.halfDuplex, m.sending != 0);
                EXPECT_EQ(link.counted, link.powerMw >= floorMw);
                const bool locksIt = link.counted && m.locked == 0 && m.sending == 0 && link.powerMw >= sensingMw;
                EXPECT_EQ(link.locked, locksIt);
                if (link.counted) m.heard += Reception::unitsOf(link.powerMw);
                if (locksIt) m.locked = frame->id;
            }
            onAir.push_back(std::move(frame));
        } else {
            const std::size_t which = random() % onAir.size();
            std::unique_ptr<Frame> frame = std::move(onAir[which]);
            onAir.erase(onAir.begin() + static_cast<std::ptrdiff_t>(which));
            for (Link& link : frame->links) {
                Model& m = model[link.receiver];
                const bool wasLocked = m.locked == frame->id;
                const bool halfBefore = link.halfDuplex;
                const double total = reception.frameEnds(frame->id, frame->start, link);
                if (wasLocked) m.locked = 0;
                EXPECT_EQ(link.halfDuplex, halfBefore || (link.counted && m.sendStart >= frame->start));
                if (!link.counted) continue;
                m.heard -= Reception::unitsOf(link.powerMw);
                EXPECT_EQ(total, mwOf(m.heard));
                reception.setSensedPower(link.receiver, total);  // as the medium does
                locks += link.locked;
                halves += link.halfDuplex;
                ++ends;
            }
            reception.stopSending(frame->sender);
            model[frame->sender].sending = 0;
        }
        for (Reception::Slot r = 0; r < kStations; ++r) {
            ASSERT_EQ(reception.sensesBusy(r), mwOf(model[r].heard) >= sensingMw) << "station " << r << " op " << op;
            ASSERT_EQ(reception.sending(r), model[r].sending != 0) << "station " << r << " op " << op;
        }
    }
    // The walk saw every case: locks, half-duplex losses, and many ends.
    EXPECT_GT(locks, 100U);
    EXPECT_GT(halves, 100U);
    EXPECT_GT(ends, 10000U);
}

/// One interference-only link of `units` to station `r`.
StepLinks interferenceOf(Reception::Slot r, Reception::Units units) {
    StepLinks step;
    step.receivers.push_back(r);
    step.bin.push_back(0);
    step.distance.push_back(300);
    step.tier.push_back(StepLinks::kInterference);
    step.units.push_back(units);
    return step;
}

TEST_F(ReceptionTest, ASumsMilliwattsAreThoseOfThe128BitConversionAtEveryMagnitude) {
    // The power a station hears, in mW, for sums from one unit to far above 1 mW (2^64 units), among them
    // the values either side of 2^64 and ones whose low bits must round: the very double the 128-bit
    // integer's conversion gives.
    using Units = Reception::Units;
    std::vector<Units> sums;
    for (int bits = 1; bits <= 100; ++bits) {
        const Units top = Units{1} << (bits - 1);
        sums.push_back(top);
        sums.push_back(top + 1);
        sums.push_back((top << 1) - 1);
    }
    std::mt19937_64 random(64);
    for (int k = 0; k < 2000; ++k) {
        const int shift = static_cast<int>(random() % 100);
        sums.push_back(((Units{random()} << 64) | random()) >> shift);
    }
    std::vector<Link> none;
    for (const Units units : sums) {
        if (units == 0) continue;
        const StepLinks step = interferenceOf(1, units);
        reception.frameStarts(1, step, none);
        const double exact = static_cast<double>(units) / 18446744073709551616.0;
        ASSERT_EQ(reception.leave(1, 0), exact) << "high word " << static_cast<std::uint64_t>(units >> 64)
                                                << ", low word " << static_cast<std::uint64_t>(units);
        ASSERT_EQ(reception.leave(1, units), 0.0);
    }
}

TEST_F(ReceptionTest, AFarCellsStationsSenseTheirSumWhateverCellsTheSensingSkips) {
    // 40 stations in four far cells, moving between them at each "step", hear individual links and their
    // cells' fields rising and falling, all near the sensing threshold (−85 dBm): after every change each
    // station senses busy exactly when its links' sum plus its cell's field reaches the threshold, and the
    // changes reported are exactly those (a far cell whose walk were skipped when a member would have changed
    // shows here: the check kept for any such lever).
    constexpr int kStations = 40;
    for (int k = 3; k < kStations; ++k) reception.addStation();
    using Units = Reception::Units;
    const double sensingMw = dbToLinear(settings.sensingDbm);
    const auto mwOf = [](Units u) { return static_cast<double>(u) / 18446744073709551616.0; };
    ChannelStations stations;
    for (int k = 0; k < kStations; ++k) {
        const auto s = stations.add("v" + std::to_string(k), static_cast<std::uint32_t>(k));
        stations.present[s] = 1;
    }
    std::mt19937_64 random(12);
    std::uniform_real_distribution<double> dbm(-100, -84);
    std::vector<Units> heard(kStations, 0), field;
    std::vector<std::int32_t> cellOf(kStations, -1);
    std::vector<char> busy(kStations, 0);
    FarCells cells(100);  // one for the run, as the medium's: a cell keeps its id from step to step
    struct OnAir {
        StepLinks step;
        bool far;
    };
    std::vector<OnAir> onAir;
    std::vector<Link> none;
    std::size_t skipped = 0, changes = 0;
    for (int op = 0; op < 20000; ++op) {
        const auto choice = random() % 16;
        if (op == 0 || choice == 0) {
            // A step: every station at a random place in a 200 m square (four 100 m cells).
            for (int k = 0; k < kStations; ++k) {
                stations.x[k] = static_cast<double>(random() % 200) + 0.5;
                stations.y[k] = static_cast<double>(random() % 200) + 0.5;
            }
            cells.newStep(stations);
            reception.moveStations(cells);
            for (int k = 0; k < kStations; ++k) cellOf[k] = cells.cellOf(k);
            field.resize(cells.cells(), 0);
        } else if (onAir.empty() || choice < 9) {
            OnAir frame;
            frame.far = random() % 2 == 0;
            if (frame.far) {
                frame.step = farCells({{static_cast<std::int32_t>(random() % field.size()), dbm(random)}});
                field[frame.step.farCell[0]] += frame.step.farUnits[0];
            } else {
                const auto r = static_cast<Reception::Slot>(random() % kStations);
                frame.step = interferenceOf(r, Reception::unitsOf(dbToLinear(dbm(random))));
                heard[r] += frame.step.units[0];
            }
            reception.frameStarts(static_cast<Reception::FrameId>(op + 1), frame.step, none);
            onAir.push_back(std::move(frame));
        } else {
            const std::size_t which = random() % onAir.size();
            const OnAir frame = std::move(onAir[which]);
            onAir.erase(onAir.begin() + static_cast<std::ptrdiff_t>(which));
            if (frame.far) {
                reception.farEnds(frame.step);
                field[frame.step.farCell[0]] -= frame.step.farUnits[0];
            } else {
                const Reception::Slot r = frame.step.receivers[0];
                reception.setSensedPower(r, reception.leave(r, frame.step.units[0]));  // as the medium does
                heard[r] -= frame.step.units[0];
            }
        }
        std::vector<std::pair<Reception::Slot, bool>> expected;
        for (Reception::Slot r = 0; r < kStations; ++r) {
            const Units total = heard[r] + (cellOf[r] >= 0 ? field[cellOf[r]] : Units{0});
            const bool now = mwOf(total) >= sensingMw;
            if (now != static_cast<bool>(busy[r])) expected.emplace_back(r, now);
            busy[r] = now;
            ASSERT_EQ(reception.sensesBusy(r), now) << "station " << r << " op " << op;
        }
        std::sort(log.changes.begin(), log.changes.end());
        ASSERT_EQ(log.changes, expected) << "op " << op;
        changes += expected.size();
        skipped += expected.empty();
        log.changes.clear();
    }
    // Both cases were seen many times: changes of sense, and changes of power that changed no sense.
    EXPECT_GT(changes, 300U);
    EXPECT_GT(skipped, 2000U);
}

}  // namespace
}  // namespace sbsim::radio
