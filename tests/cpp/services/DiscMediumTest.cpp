// The V2X medium on hand-made snapshots: range (inclusive), latency (exact, also below a
// millisecond), no delivery to the sender or to vehicles without services, per-type counts, the
// packet-error model (probability, statistics, seeding, no draws when reception is certain), and
// messages to vehicles that left before the delivery time.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "ServicesTestSupport.h"
#include "TestPrinters.h"
#include "sbsim/radio/disc/DiscMedium.h"
#include "sbsim/services/Middleware.h"

namespace sbsim::services::test {
namespace {

constexpr std::string_view kAllButBare = R"(<services>
    <service type="TestProbe"><filters><name pattern="bare.*" match="inverse"/></filters></service>
</services>)";

radio::DiscSettings disc(double range, SimTime latency = SimTime::fromMilliseconds(1),
                         std::optional<double> fadeStart = {}) {
    radio::DiscSettings s;
    s.range = range;
    s.latency = latency;
    s.fadeStart = fadeStart;
    return s;
}

/// Sends a `type` message numbered `seq` from `sender`'s probe at `t` (after the step due then).
void sendAt(Harness& h, SimTime t, const std::string& sender, const std::string& type = "Ping", int seq = 0) {
    h.at(t, [&h, sender, type, seq] { h.log.probe(sender).sendNow(std::make_unique<TestMessage>(type, seq)); });
}

std::size_t received(const Harness& h, const std::string& vehicle) {
    const ProbeRecord* r = h.log.find(vehicle);
    return r == nullptr ? 0 : r->indications.size();
}

/// The sequence numbers `vehicle` heard, in the order it heard them.
std::vector<int> heardSeqs(const Harness& h, const std::string& vehicle) {
    std::vector<int> seqs;
    if (const ProbeRecord* r = h.log.find(vehicle))
        for (const Indication& i : r->indications) seqs.push_back(i.seq);
    return seqs;
}

/// A trace that keeps nothing: its presence alone makes the medium visit each link.
struct QuietTrace : radio::MessageTrace {
    void record(const radio::TraceLine&, SimTime) override {}
};

using Counts = std::map<std::string, std::pair<std::uint64_t, std::uint64_t>>;
Counts countsOf(const radio::DiscMedium& m) {
    Counts out;
    for (const auto& [type, c] : m.counts()) out[type] = {c.sent, c.delivered};
    return out;
}

TEST(DiscMedium, RangeBoundaryIsInclusive) {
    Harness h(kAllButBare, disc(500));
    h.step(secs(1), {vehicle("s", 0, 0), vehicle("edge", 500, 0), vehicle("diagonal", 300, -400),
                     vehicle("beyond", std::nextafter(500.0, 1000.0), 0), vehicle("far", 0, 1200)});
    sendAt(h, secs(1), "s");
    h.sim.run(secs(2));
    EXPECT_EQ(received(h, "edge"), 1u) << "exactly at the range";
    EXPECT_EQ(received(h, "diagonal"), 1u) << "exactly at the range (3-4-5)";
    EXPECT_EQ(received(h, "beyond"), 0u) << "one ulp beyond the range";
    EXPECT_EQ(received(h, "far"), 0u);
    EXPECT_EQ(countsOf(h.medium), (Counts{{"Ping", {1, 2}}}));
}

TEST(DiscMedium, NoDeliveryToTheSenderNorToVehiclesWithoutServices) {
    Harness h(kAllButBare, disc(100));
    h.step(secs(1), {vehicle("s"), vehicle("a"), vehicle("bare1"), vehicle("bare2", 10, 0)});
    sendAt(h, secs(1), "s", "Ping", 1);
    sendAt(h, secs(1), "a", "Ping", 2);
    // A sender that is not on the road: counted as sent, heard by nobody.
    h.at(secs(1), [&] { h.medium.broadcast("ghost", std::make_unique<TestMessage>("Ping", 3)); });
    h.sim.run(secs(2));
    ASSERT_EQ(received(h, "s"), 1u);
    EXPECT_EQ(h.log.find("s")->indications[0].sender, "a");
    ASSERT_EQ(received(h, "a"), 1u);
    EXPECT_EQ(h.log.find("a")->indications[0].sender, "s");
    EXPECT_TRUE(h.log.of("bare1").empty() && h.log.of("bare2").empty());
    EXPECT_EQ(h.manager.middlewareOf("bare1"), nullptr);
    EXPECT_EQ(countsOf(h.medium), (Counts{{"Ping", {3, 2}}})) << "vehicles without services are no receivers";
}

TEST(DiscMedium, DeliversExactlyAfterTheLatencyWithSenderAndSendTime) {
    Harness h(kAllButBare, disc(100, SimTime::fromMilliseconds(250)));
    h.step(secs(1), {vehicle("s"), vehicle("r", 30, 40)});
    sendAt(h, secs(1), "s", "Ping", 1);
    sendAt(h, secs(1.05), "s", "Ping", 2);
    h.sim.run(secs(3));
    const ProbeRecord* r = h.log.find("r");
    ASSERT_EQ(r->indications.size(), 2u);
    EXPECT_EQ(r->indications[0].at, secs(1.25));
    EXPECT_EQ(r->indications[0].sentAt, secs(1));
    EXPECT_EQ(r->indications[0].sender, "s");
    EXPECT_EQ(r->indications[0].seq, 1);
    EXPECT_EQ(r->indications[1].at, secs(1.3));
    EXPECT_EQ(r->indications[1].sentAt, secs(1.05));
    EXPECT_EQ(r->indications[1].seq, 2);
}

TEST(DiscMedium, LatenciesBelowAMillisecondAndZeroAreExact) {
    for (const SimTime latency : {SimTime::zero(), SimTime::fromNanoseconds(1), SimTime::fromNanoseconds(300'000),
                                  SimTime::fromNanoseconds(999'999), SimTime::fromMilliseconds(999)}) {
        SCOPED_TRACE("latency " + latency.str() + " s");
        Harness h(kAllButBare, disc(100, latency));
        for (int t = 1; t <= 3; ++t) h.step(secs(t), {vehicle("s"), vehicle("r", 10, 0)});
        sendAt(h, secs(2), "s", "Ping", 7);
        h.sim.run(secs(4));
        const ProbeRecord* r = h.log.find("r");
        ASSERT_EQ(r->indications.size(), 1u);
        EXPECT_EQ(r->indications[0].at, secs(2) + latency);
        EXPECT_EQ(r->indications[0].at.raw(), 2'000'000'000 + latency.raw());
        EXPECT_EQ(r->indications[0].sentAt, secs(2));
    }
}

// The medium keeps its delivery events and reuses them: several frames on the air at once each
// reach their receivers with their own message, in the order sent, and a later wave (on the events
// the first one freed) delivers its own messages, not the first wave's.
TEST(DiscMedium, FramesOnTheAirAtOnceAndLaterOnesDeliverTheirOwnMessages) {
    Harness h(kAllButBare, disc(500, SimTime::fromMilliseconds(10)));
    h.step(secs(1), {vehicle("a", 0, 0), vehicle("b", 100, 0), vehicle("c", 200, 0)});
    for (int wave = 0; wave < 3; ++wave) {
        for (int k = 0; k < 4; ++k) {
            const SimTime t = secs(1) + SimTime::fromMilliseconds(100 * wave + 2 * k);  // 4 frames within 10 ms
            sendAt(h, t, k % 2 == 0 ? "a" : "b", "Ping", 10 * wave + k);
        }
    }
    h.sim.run(secs(2));
    EXPECT_EQ(heardSeqs(h, "c"), (std::vector<int>{0, 1, 2, 3, 10, 11, 12, 13, 20, 21, 22, 23}));
    EXPECT_EQ(heardSeqs(h, "a"), (std::vector<int>{1, 3, 11, 13, 21, 23}));
    EXPECT_EQ(heardSeqs(h, "b"), (std::vector<int>{0, 2, 10, 12, 20, 22}));
    const ProbeRecord* c = h.log.find("c");
    ASSERT_NE(c, nullptr);
    for (const Indication& i : c->indications) {
        const int wave = i.seq / 10, k = i.seq % 10;
        EXPECT_EQ(i.at, secs(1) + SimTime::fromMilliseconds(100 * wave + 2 * k + 10)) << "seq " << i.seq;
        EXPECT_EQ(i.sender, k % 2 == 0 ? "a" : "b") << "seq " << i.seq;
    }
}

TEST(DiscMedium, CountsSentAndDeliveredPerType) {
    Harness h(kAllButBare, disc(100));
    h.step(secs(1),
           {vehicle("s"), vehicle("r1", 50, 0), vehicle("r2", 0, 50), vehicle("r3", 0, 150), vehicle("bare", 1, 0)});
    for (int i = 0; i < 3; ++i) sendAt(h, secs(1), "s", "Alpha", i);
    for (int i = 0; i < 2; ++i) sendAt(h, secs(1.5), "s", "Beta", i);
    h.at(secs(1), [&] { h.medium.broadcast("ghost", std::make_unique<TestMessage>("Gamma", 0)); });
    h.sim.run(secs(2));
    EXPECT_EQ(countsOf(h.medium), (Counts{{"Alpha", {3, 6}}, {"Beta", {2, 4}}, {"Gamma", {1, 0}}}));
    EXPECT_EQ(received(h, "r1"), 5u);
    EXPECT_EQ(received(h, "r2"), 5u);
    EXPECT_EQ(received(h, "r3"), 0u);
}

TEST(DiscMedium, CountsFollowEachFramesTypeWhenTypesAlternate) {
    // The medium remembers the counts it found last (by type name): frames of one class whose names
    // alternate, sent and delivered interleaved, each count under their own name.
    Harness h(kAllButBare, disc(100));
    h.step(secs(1), {vehicle("s"), vehicle("r1", 50, 0), vehicle("r2", 0, 150)});
    const std::vector<std::string> types = {"Alpha", "Beta", "Alpha", "Gamma", "Beta", "Alpha", "Alpha"};
    for (std::size_t i = 0; i < types.size(); ++i)
        sendAt(h, secs(1.0 + 0.0005 * static_cast<double>(i)), "s", types[i]);
    h.sim.run(secs(2));
    EXPECT_EQ(countsOf(h.medium), (Counts{{"Alpha", {4, 4}}, {"Beta", {2, 2}}, {"Gamma", {1, 1}}}));
    EXPECT_EQ(received(h, "r1"), types.size());
}

TEST(DiscMedium, AStationsFramesByIndexAndByNameShareOneNumbering) {
    // A middleware hands its frames over with its index (broadcastFrom); a frame sent by name from
    // the same station continues the same numbering. A broadcastFrom() that throws leaves no index
    // behind, even for the same string holding another name next.
    Harness h(kAllButBare, disc(100));
    h.step(secs(1), {vehicle("s"), vehicle("t", 10, 0), vehicle("r", 5, 0)});
    sendAt(h, secs(1), "s", "Ping", 1);
    h.at(secs(1), [&] { h.medium.broadcast("s", std::make_unique<TestMessage>("Ping", 2)); });
    sendAt(h, secs(1), "s", "Ping", 3);
    h.at(secs(1), [&] {
        std::string name = "s";
        EXPECT_THROW(h.medium.broadcastFrom(h.medium.stationIndex("s"), name, nullptr), std::invalid_argument);
        name = "t";
        h.medium.broadcast(name, std::make_unique<TestMessage>("Ping", 4));
    });
    h.sim.run(secs(2));
    const ProbeRecord* r = h.log.find("r");
    ASSERT_NE(r, nullptr);
    std::vector<std::tuple<std::string, int, std::uint64_t>> got;
    for (const Indication& i : r->indications) got.emplace_back(i.sender, i.seq, i.sequence);
    using Frame = std::tuple<std::string, int, std::uint64_t>;
    EXPECT_EQ(got, (std::vector<Frame>{{"s", 1, 0}, {"s", 2, 1}, {"s", 3, 2}, {"t", 4, 0}}));
}

TEST(DiscMedium, UsesTheCurrentStepsPositions) {
    Harness h(kAllButBare, disc(100));
    // r moves in and out of range from step to step; s sends once per step. Bystanders without
    // services make the neighbour grid look up cells instead of scanning every vehicle.
    const double xs[] = {150, 50, 150, 50, 99};
    for (int t = 1; t <= 5; ++t) {
        std::vector<VehicleSnapshot::Vehicle> vehicles = {vehicle("s"), vehicle("r", xs[t - 1], 0)};
        for (int k = 0; k < 30; ++k) vehicles.push_back(vehicle("bare" + std::to_string(k), 1000 + 300 * k, 1000));
        h.step(secs(t), std::move(vehicles));
        sendAt(h, secs(t), "s", "Ping", t);
    }
    h.sim.run(secs(6));
    std::vector<int> heard;
    for (const Indication& i : h.log.find("r")->indications) heard.push_back(i.seq);
    EXPECT_EQ(heard, (std::vector<int>{2, 4, 5}));
}

TEST(DiscMedium, MessageToAVehicleThatLeftBeforeDeliveryIsDropped) {
    Harness h(kAllButBare, disc(100, SimTime::fromMilliseconds(500)));
    h.step(secs(1), {vehicle("s"), vehicle("b", 10, 0), vehicle("c", 20, 0)});
    sendAt(h, secs(1), "s", "Ping", 1);
    h.step(secs(1.2), {vehicle("s"), vehicle("c", 20, 0)});  // b leaves while message 1 is in the air
    sendAt(h, secs(2), "s", "Ping", 2);
    h.step(secs(2.5), {vehicle("s")});  // c leaves exactly at message 2's delivery time: the step comes first
    h.sim.run(secs(4));
    const ProbeRecord* b = h.log.find("b");
    const ProbeRecord* c = h.log.find("c");
    EXPECT_TRUE(b->indications.empty());
    EXPECT_EQ(b->finishes, std::vector<SimTime>{secs(1.2)});
    ASSERT_EQ(c->indications.size(), 1u);
    EXPECT_EQ(c->indications[0].seq, 1);
    EXPECT_EQ(c->indications[0].at, secs(1.5));
    EXPECT_EQ(countsOf(h.medium), (Counts{{"Ping", {2, 1}}})) << "dropped messages are not counted as delivered";
    EXPECT_EQ(b->callsAfterFinish + c->callsAfterFinish, 0);
}

// The medium keeps each station's receiving side across steps and other stations' departures
// and arrivals: a station that leaves is no longer reached (its module is gone), and one that comes
// back under the same id is reached through its new module, also by a frame on the air meanwhile.
TEST(DiscMedium, AStationThatLeavesAndComesBackIsReachedThroughItsNewModule) {
    Harness h(kAllButBare, disc(100, SimTime::fromMilliseconds(150)));
    const auto others = [](int k) {
        // Other stations come and go at every step: module changes that leave b's module as it is.
        return vehicle("o" + std::to_string(k), 40, 10);
    };
    h.step(secs(1.0), {vehicle("b", 10, 0), others(1), vehicle("s")});
    sendAt(h, secs(1.0), "s", "Ping", 1);  // b's first module, delivered at 1.15 s
    h.step(secs(1.1), {vehicle("b", 10, 0), others(2), vehicle("s")});
    sendAt(h, secs(1.1), "s", "Ping", 2);  // on the air while b leaves at 1.2 s and comes back at 1.3 s: dropped
    h.step(secs(1.2), {others(3), vehicle("s")});
    sendAt(h, secs(1.2), "s", "Ping", 3);  // b is away
    h.step(secs(1.3), {vehicle("b", 10, 0), others(4), vehicle("s")});
    sendAt(h, secs(1.3), "s", "Ping", 4);  // b's second module
    h.step(secs(1.4), {vehicle("b", 10, 0), others(5), vehicle("s")});
    sendAt(h, secs(1.4), "s", "Ping", 5);
    h.sim.run(secs(2));
    const std::vector<ProbeRecord*> b = h.log.of("b");
    ASSERT_EQ(b.size(), 2u);
    const auto seqs = [](const ProbeRecord& r) {
        std::vector<int> out;
        for (const Indication& i : r.indications) out.push_back(i.seq);
        return out;
    };
    EXPECT_EQ(seqs(*b[0]), (std::vector<int>{1}));
    EXPECT_EQ(seqs(*b[1]), (std::vector<int>{4, 5})) << "the new module, not the old one";
    EXPECT_EQ(b[0]->callsAfterFinish + b[1]->callsAfterFinish, 0);
}

// At 0.1 s steps a sender's neighbours come from lists kept across steps and its receivers stay
// one list while they are the same: each frame still reaches exactly the stations in range at its
// step, when one drives in and out of range, one jumps from far away (past the lists' skin), one
// joins the run, and the receivers are unchanged for several steps in between.
TEST(DiscMedium, KeptNeighbourhoodsAndListsFollowEachStep) {
    Harness h(kAllButBare, disc(100));
    const double in[] = {150, 150, 50, 50, 50, 150, 150, 50, 50, 50};  // c: in range at steps 3-5 and 8-10
    for (int k = 1; k <= 10; ++k) {
        std::vector<VehicleSnapshot::Vehicle> vehicles = {vehicle("a", 50, 0), vehicle("c", in[k - 1], 0),
                                                          vehicle("e", k < 6 ? 3000 : 60, 0), vehicle("s")};
        if (k >= 7) vehicles.push_back(vehicle("d", -40, 0));  // joins at step 7
        for (int b = 0; b < 30; ++b) vehicles.push_back(vehicle("bare" + std::to_string(b), 30.0 * b, 500 + 90.0 * b));
        const SimTime t = secs(1 + 0.1 * k);
        h.step(t, std::move(vehicles));
        sendAt(h, t, "s", "Ping", k);
    }
    h.sim.run(secs(3));
    const auto heard = [&](const std::string& id) { return heardSeqs(h, id); };
    EXPECT_EQ(heard("a"), (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
    EXPECT_EQ(heard("c"), (std::vector<int>{3, 4, 5, 8, 9, 10}));
    EXPECT_EQ(heard("e"), (std::vector<int>{6, 7, 8, 9, 10})) << "a jump from 3 km into range";
    EXPECT_EQ(heard("d"), (std::vector<int>{7, 8, 9, 10})) << "a vehicle that joined";
    EXPECT_EQ(countsOf(h.medium), (Counts{{"Ping", {10, 25}}}));
}

// A sender's receivers kept as its last list while the same stations are in range: kept only
// while no module joined or left, since a station that left and came back between two of the
// sender's frames is the same station with another receiving side. Here b leaves at step 3 (s
// sends nothing then) and comes back at step 4, after "a0" (out of range) joined, which may take
// the memory b's old side freed: step 4's frames must reach b's new side, and a0 nothing.
TEST(DiscMedium, AStationBackWithAnotherReceiverIsReachedThere) {
    Harness h(kAllButBare, disc(100));
    for (int k = 1; k <= 6; ++k) {
        std::vector<VehicleSnapshot::Vehicle> vehicles = {vehicle("a", 50, 0), vehicle("s")};
        if (k != 3) vehicles.push_back(vehicle("b", 60, 0));
        if (k >= 4) vehicles.push_back(vehicle("a0", 3000, 0));
        for (int b = 0; b < 30; ++b) vehicles.push_back(vehicle("bare" + std::to_string(b), 30.0 * b, 500 + 90.0 * b));
        const SimTime t = secs(1 + 0.1 * k);
        h.step(t, std::move(vehicles));
        if (k != 3) sendAt(h, t, "s", "Ping", k);
    }
    h.sim.run(secs(3));
    std::map<std::string, std::vector<int>> heard;  // over every record of a vehicle (b has two)
    for (const auto& r : h.log.records) {
        if (r->type != "TestProbe") continue;
        for (const Indication& i : r->indications) heard[r->vehicle].push_back(i.seq);
    }
    EXPECT_EQ(heard["a"], (std::vector<int>{1, 2, 4, 5, 6}));
    EXPECT_EQ(heard["b"], (std::vector<int>{1, 2, 4, 5, 6})) << "b's new side hears the frames after it came back";
    EXPECT_TRUE(heard["a0"].empty()) << "out of range";
    ASSERT_NE(h.log.find("b"), nullptr);
    EXPECT_EQ(h.log.find("b")->indications.size(), 2u) << "b's first side heard the frames before it left";
    EXPECT_EQ(countsOf(h.medium), (Counts{{"Ping", {5, 10}}}));
}

// The medium finds in its loop over the neighbours whether a sender's receivers are its last list
// (then handed again, uncompared): a list as long as the last with another station at its end or
// at its start, a shorter and a longer one must each be a new list. The stations cross the range's
// edge by 2.5 m a step (within the kept lists' skin: found among a list's own candidates) and, in
// a second run, jump 100 m a step (past the skin: found among its newcomers); no module changes.
TEST(DiscMedium, AChangedListOfTheSameModulesIsANewList) {
    for (const auto& [in, out] : {std::pair{99.0, 101.5}, std::pair{50.0, 150.0}}) {
        Harness h(kAllButBare, disc(100));
        // Per step, who is in range: {a, c}, {a, d}, {c, d}, {c, d}, {c}, {c, d}, {a, c, d}, {a, c, d}.
        const std::vector<std::string> lists = {"ac", "ad", "cd", "cd", "c", "cd", "acd", "acd"};
        for (std::size_t k = 0; k < lists.size(); ++k) {
            const auto at = [&](char id) { return lists[k].find(id) != std::string::npos ? in : out; };
            std::vector<VehicleSnapshot::Vehicle> vehicles = {vehicle("a", at('a'), 0), vehicle("c", 0, at('c')),
                                                              vehicle("d", -at('d'), 0), vehicle("s")};
            for (int b = 0; b < 30; ++b)
                vehicles.push_back(vehicle("bare" + std::to_string(b), 30.0 * b, 500 + 90.0 * b));
            const SimTime t = secs(1 + 0.1 * static_cast<double>(k + 1));
            h.step(t, std::move(vehicles));
            sendAt(h, t, "s", "Ping", static_cast<int>(k + 1));
        }
        h.sim.run(secs(3));
        EXPECT_EQ(heardSeqs(h, "a"), (std::vector<int>{1, 2, 7, 8})) << "in " << in;
        EXPECT_EQ(heardSeqs(h, "c"), (std::vector<int>{1, 3, 4, 5, 6, 7, 8})) << "in " << in;
        EXPECT_EQ(heardSeqs(h, "d"), (std::vector<int>{2, 3, 4, 6, 7, 8})) << "in " << in;
        EXPECT_EQ(countsOf(h.medium), (Counts{{"Ping", {8, 17}}}));
    }
}

// Without packet errors or a trace a frame takes its sender's receivers of the step (taken once
// per step and module change) instead of visiting each link: the same stations hear the same
// frames in the same order, with the same counts per distance bin, as with a trace (which visits
// each link), with several frames a step and a station departing at the next.
TEST(DiscMedium, AFrameReachesTheSameStationsTracedOrNot) {
    QuietTrace quiet;
    const auto run = [&](bool traced) {
        Harness h(kAllButBare, disc(300));
        if (traced) h.medium.setTrace(&quiet);
        std::vector<VehicleSnapshot::Vehicle> first;
        std::vector<std::string> senders;
        for (int k = 0; k < 40; ++k) {
            const std::string id = (k % 7 == 3 ? "bare" : "v") + std::to_string(k);
            first.push_back(vehicle(id, 37.0 * (k % 10), 61.0 * (k / 10)));
            if (k % 7 != 3 && k % 3 == 0) senders.push_back(id);
        }
        h.step(secs(1), first);
        std::vector<VehicleSnapshot::Vehicle> second = first;
        second.push_back(vehicle("late", 100, 100));
        h.step(secs(1.5), second);
        int seq = 0;
        for (const SimTime t : {secs(1), secs(1.2), secs(1.5), secs(1.7)}) {
            for (const std::string& id : senders) sendAt(h, t, id, "Ping", seq++);
        }
        h.sim.run(secs(2));
        std::map<std::string, std::vector<std::string>> heard;
        for (const auto& v : second) {
            if (const ProbeRecord* r = h.log.find(v.id))
                for (const Indication& i : r->indications)
                    heard[v.id].push_back(i.sender + "#" + std::to_string(i.seq));
        }
        const auto& c = h.medium.counts().at("Ping");
        return std::make_tuple(heard, c.linkStations, c.linkReceptions, c.delivered);
    };
    const auto plain = run(false);
    EXPECT_EQ(plain, run(true));
    EXPECT_FALSE(std::get<0>(plain).at("late").empty());
    EXPECT_GT(std::get<3>(plain), 100u);
}

// Vehicles that all move far each step (the kept lists restart at nearly every step, and the
// medium then takes each step's grid instead): each frame still reaches exactly the stations in range.
TEST(DiscMedium, NeighboursFollowVehiclesThatAllMoveFarEachStep) {
    Harness h(kAllButBare, disc(100));
    for (int k = 1; k <= 12; ++k) {
        const double spacing = k % 2 == 0 ? 30 : 45;  // v1..v3 in range, or v1..v2
        std::vector<VehicleSnapshot::Vehicle> vehicles;
        for (int i = 0; i < 80; ++i)
            vehicles.push_back(vehicle("v" + std::to_string(100 + i), 1000.0 * k + spacing * i, 0));
        const SimTime t = secs(1 + 0.1 * k);
        h.step(t, std::move(vehicles));
        sendAt(h, t, "v100", "Ping", k);
    }
    h.sim.run(secs(3));
    const auto heard = [&](const std::string& id) { return heardSeqs(h, id); };
    EXPECT_EQ(heard("v101"), (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}));
    EXPECT_EQ(heard("v102"), (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}));
    EXPECT_EQ(heard("v103"), (std::vector<int>{2, 4, 6, 8, 10, 12}));
    EXPECT_TRUE(heard("v104").empty());
    EXPECT_EQ(countsOf(h.medium), (Counts{{"Ping", {12, 30}}}));
}

// A frame that takes its sender's receivers counts them per 50 m bin without a division per link:
// at and around the bins' edges (one ulp either side) the counts are those of the traced run, which
// counts each link as Medium::countLink does.
TEST(DiscMedium, DistanceBinsAtTheirEdgesCountAsPerLink) {
    QuietTrace quiet;
    const auto run = [&](bool traced) {
        Harness h(kAllButBare, disc(400));
        std::vector<VehicleSnapshot::Vehicle> vehicles = {vehicle("s")};
        int n = 0;
        for (const double edge : {50.0, 100.0, 150.0, 200.0, 250.0, 300.0, 350.0, 400.0}) {
            for (const double x : {std::nextafter(edge, 0.0), edge, std::nextafter(edge, 1000.0)})
                vehicles.push_back(vehicle("r" + std::to_string(n++), x, 0));
            vehicles.push_back(vehicle("r" + std::to_string(n++), edge * 0.6, edge * 0.8));  // 3-4-5: exact
        }
        if (traced) h.medium.setTrace(&quiet);
        h.step(secs(1), vehicles);
        sendAt(h, secs(1), "s", "Ping", 1);
        h.sim.run(secs(2));
        const auto& c = h.medium.counts().at("Ping");
        return std::make_pair(c.linkStations, c.linkReceptions);
    };
    const auto plain = run(false);
    EXPECT_EQ(plain, run(true));
    EXPECT_EQ(plain.first, (std::vector<std::uint64_t>{1, 4, 4, 4, 4, 4, 4, 4, 2}));
}

// Vehicles that all move far each step (the kept lists do not last: each sender's neighbours come
// from the step's grid, read as a bit set with the grid test's own squared distances), most of
// them sending at each step, a few at steps 5-6: each frame reaches exactly the stations (with
// services) in range at its step, in the order sent, counted in the distance bins of its links as
// Medium::countLink counts them, traced or not.
TEST(DiscMedium, EachFrameReachesTheStationsInRangeWhenAllMoveFarEachStep) {
    QuietTrace quiet;
    const auto place = [](int i, int k) {
        return std::pair{1000.0 * k + 40.0 * (i % 10) + 7.0 * k * (i % 3), 35.0 * (i / 10) - 11.0 * k * (i % 4 == 1)};
    };
    const auto id = [](int i) { return (i % 11 == 5 ? "bare" : "v") + std::to_string(100 + i); };
    const auto run = [&](bool traced) {
        Harness h(kAllButBare, disc(150));
        if (traced) h.medium.setTrace(&quiet);
        int seq = 0;
        for (int k = 1; k <= 8; ++k) {
            std::vector<VehicleSnapshot::Vehicle> vehicles;
            for (int i = 0; i < 90; ++i) vehicles.push_back(vehicle(id(i), place(i, k).first, place(i, k).second));
            const SimTime t = secs(1 + 0.1 * k);
            h.step(t, std::move(vehicles));
            for (int i = 0; i < 90; ++i) {
                const bool sends = k == 5 || k == 6 ? i % 30 == 1 : i % 11 != 5;
                if (sends) sendAt(h, t, id(i), "Ping", seq++);
            }
        }
        h.sim.run(secs(3));
        std::map<std::string, std::vector<std::string>> heard;
        for (int i = 0; i < 90; ++i) {
            if (const ProbeRecord* r = h.log.find(id(i)))
                for (const Indication& ind : r->indications)
                    heard[id(i)].push_back(ind.sender + "#" + std::to_string(ind.seq));
        }
        const auto& c = h.medium.counts().at("Ping");
        return std::make_tuple(heard, c.linkStations, c.delivered);
    };
    // Brute force: per frame, the stations with services within 150 m at its step, in sending order.
    std::map<std::string, std::vector<std::string>> heard;
    std::vector<std::uint64_t> bins;
    std::uint64_t delivered = 0;
    int seq = 0;
    for (int k = 1; k <= 8; ++k) {
        for (int s = 0; s < 90; ++s) {
            const bool sends = k == 5 || k == 6 ? s % 30 == 1 : s % 11 != 5;
            if (!sends) continue;
            const int frame = seq++;
            for (int r = 0; r < 90; ++r) {
                const double dx = place(r, k).first - place(s, k).first;
                const double dy = place(r, k).second - place(s, k).second;
                if (r == s || r % 11 == 5 || dx * dx + dy * dy > 150.0 * 150.0) continue;
                heard[id(r)].push_back(id(s) + "#" + std::to_string(frame));
                const auto bin = static_cast<std::size_t>(std::sqrt(dx * dx + dy * dy) / 50);
                if (bins.size() <= bin) bins.resize(bin + 1);
                ++bins[bin];
                ++delivered;
            }
        }
    }
    const auto plain = run(false);
    EXPECT_EQ(std::get<0>(plain), heard);
    EXPECT_EQ(std::get<1>(plain), bins);
    EXPECT_EQ(std::get<2>(plain), delivered);
    EXPECT_EQ(plain, run(true));
    EXPECT_GT(delivered, 5000u);
}

// --- packet errors ---------------------------------------------------------------------------

TEST(DiscSettings, InvalidSettingsAreRejected) {
    VehicleSnapshot snapshot;
    const auto make = [&](radio::DiscSettings s) {
        radio::DiscMedium m(s, snapshot, [](const std::string&) { return nullptr; });
    };
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(make(disc(0)), std::invalid_argument);
    EXPECT_THROW(make(disc(-1)), std::invalid_argument);
    EXPECT_THROW(make(disc(std::nan(""))), std::invalid_argument);
    EXPECT_THROW(make(disc(inf)), std::invalid_argument);
    EXPECT_THROW(make(disc(100, -SimTime::fromNanoseconds(1))), std::invalid_argument);
    EXPECT_THROW(make(disc(100, SimTime::zero(), -1.0)), std::invalid_argument);
    EXPECT_THROW(make(disc(100, SimTime::zero(), 100.5)), std::invalid_argument);
    EXPECT_NO_THROW(make(disc(100, SimTime::zero(), 100.0)));
    EXPECT_NO_THROW(make(disc(100, SimTime::zero(), 0.0)));
}

TEST(DiscSettings, ReceptionProbabilityFallsLinearlyFromFadeStartToRange) {
    VehicleSnapshot snapshot;
    const auto none = [](const std::string&) -> Middleware* { return nullptr; };
    const radio::DiscMedium lossless(disc(200), snapshot, none);
    EXPECT_EQ(lossless.receptionProbability(0), 1.0);
    EXPECT_EQ(lossless.receptionProbability(200), 1.0);
    EXPECT_EQ(lossless.receptionProbability(std::nextafter(200.0, 300.0)), 0.0);

    const radio::DiscMedium fading(disc(200, SimTime::zero(), 100.0), snapshot, none);
    EXPECT_EQ(fading.receptionProbability(0), 1.0);
    EXPECT_EQ(fading.receptionProbability(100), 1.0);
    EXPECT_DOUBLE_EQ(fading.receptionProbability(110), 0.9);
    EXPECT_DOUBLE_EQ(fading.receptionProbability(125), 0.75);
    EXPECT_DOUBLE_EQ(fading.receptionProbability(150), 0.5);
    EXPECT_DOUBLE_EQ(fading.receptionProbability(190), 0.1);
    EXPECT_EQ(fading.receptionProbability(200), 0.0);
    EXPECT_EQ(fading.receptionProbability(250), 0.0);

    const radio::DiscMedium fromZero(disc(50, SimTime::zero(), 0.0), snapshot, none);
    EXPECT_EQ(fromZero.receptionProbability(0), 1.0);
    EXPECT_DOUBLE_EQ(fromZero.receptionProbability(10), 0.8);

    const radio::DiscMedium sharp(disc(50, SimTime::zero(), 50.0), snapshot, none);  // fade start = range: no fading
    EXPECT_EQ(sharp.receptionProbability(50), 1.0);
    EXPECT_EQ(sharp.receptionProbability(50.5), 0.0);
}

/// Receivers around a sender at the origin, for range 100 and fade start 50.
const std::vector<std::pair<std::string, VehicleSnapshot::Vehicle>> kLossyReceivers = {
    {"r25", vehicle("r25", 25, 0)},     // p = 1
    {"r60", vehicle("r60", 0, 60)},     // p = 0.8
    {"r75", vehicle("r75", -75, 0)},    // p = 0.5
    {"r90", vehicle("r90", 0, -90)},    // p = 0.2
    {"r100", vehicle("r100", 100, 0)},  // p = 0: at the range
};

/// Per receiver (kLossyReceivers order), which of `n` messages sent at 2 s arrived. With
/// `warmUp` > 0, that many messages go out first at 1 s, when every receiver is within 10 m.
std::vector<std::vector<bool>> lossyRun(std::uint64_t seed, int n, int warmUp = 0, Counts* counts = nullptr) {
    Harness h(kAllButBare, disc(100, SimTime::fromMilliseconds(1), 50.0), secs(0.1), seed);
    std::vector<VehicleSnapshot::Vehicle> near = {vehicle("s")};
    std::vector<VehicleSnapshot::Vehicle> spread = {vehicle("s")};
    for (const auto& [id, v] : kLossyReceivers) {
        near.push_back(vehicle(id, 5, 5));
        spread.push_back(v);
    }
    h.step(secs(1), near);
    h.step(secs(2), spread);
    h.at(secs(1), [&] {
        for (int i = 0; i < warmUp; ++i) h.log.probe("s").sendNow(std::make_unique<TestMessage>("Warm", i));
    });
    h.at(secs(2), [&] {
        for (int i = 0; i < n; ++i) h.log.probe("s").sendNow(std::make_unique<TestMessage>("Ping", i));
    });
    h.sim.run(secs(3));
    std::vector<std::vector<bool>> out;
    for (const auto& [id, v] : kLossyReceivers) {
        std::vector<bool> got(n, false);
        int warm = 0;
        for (const Indication& i : h.log.find(id)->indications) {
            if (i.type == "Warm") {
                ++warm;
            } else {
                got.at(i.seq) = true;
            }
        }
        EXPECT_EQ(warm, warmUp) << id << ": within the fade start every message arrives";
        out.push_back(std::move(got));
    }
    if (counts != nullptr) *counts = countsOf(h.medium);
    return out;
}

TEST(MediumLoss, DeliveredFractionMatchesTheReceptionProbability) {
    constexpr int n = 4000;
    Counts counts;
    const auto got = lossyRun(11, n, 0, &counts);
    const double p[] = {1.0, 0.8, 0.5, 0.2, 0.0};
    std::uint64_t total = 0;
    for (std::size_t k = 0; k < got.size(); ++k) {
        const auto delivered = static_cast<double>(std::count(got[k].begin(), got[k].end(), true));
        total += static_cast<std::uint64_t>(delivered);
        const double tolerance = 4 * std::sqrt(p[k] * (1 - p[k]) / n);  // 4 standard deviations
        EXPECT_NEAR(delivered / n, p[k], tolerance) << kLossyReceivers[k].first;
    }
    EXPECT_EQ(std::count(got[0].begin(), got[0].end(), true), n) << "before the fade start nothing is lost";
    EXPECT_EQ(std::count(got[4].begin(), got[4].end(), true), 0) << "at the range nothing arrives";
    EXPECT_EQ(counts.at("Ping"), std::make_pair(std::uint64_t{n}, total));
}

TEST(MediumLoss, SameSeedSameDeliveriesOtherSeedOthers) {
    const auto a = lossyRun(5, 500);
    const auto b = lossyRun(5, 500);
    const auto c = lossyRun(6, 500);
    EXPECT_EQ(a, b);
    EXPECT_NE(a[2], c[2]) << "p = 0.5: 500 identical draws from another seed are practically impossible";
}

TEST(MediumLoss, NoRandomDrawsWhenReceptionIsCertain) {
    // 300 messages that every receiver gets for sure must not shift the later lossy draws.
    const auto plain = lossyRun(9, 500);
    const auto afterWarmUp = lossyRun(9, 500, 300);
    EXPECT_EQ(plain, afterWarmUp);
    EXPECT_NE(std::count(plain[2].begin(), plain[2].end(), true), 0);
    EXPECT_NE(std::count(plain[2].begin(), plain[2].end(), true), 500);
}

}  // namespace
}  // namespace sbsim::services::test
