// GeoNetworking's routing logic without the kernel: the CBF timeout, duplicate packet detection,
// contention-based forwarding inside the area (a duplicate heard before the timer cancels, one
// heard after does not forward again), the hop limit, greedy forwarding towards the area and the
// switch that turns forwarding off. Frames are made by real routers (a source's originate, a
// forwarder's takeExpired), as they are in a run.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "sbsim/radio/V2xMessage.h"
#include "sbsim/radio/geonet/CbfTimeout.h"
#include "sbsim/radio/geonet/DuplicatePacketList.h"
#include "sbsim/radio/geonet/GreedyForwarding.h"
#include "sbsim/radio/geonet/Router.h"

namespace sbsim::radio::geonet {
namespace {

using kernel::SimTime;
using V = Eigen::Vector2d;

SimTime ms(double m) { return SimTime::fromRaw(std::llround(m * 1e6)); }

/// A message that geo-broadcasts itself to `area` (or a single-hop broadcast without one).
class AreaMessage : public V2xMessage {
public:
    AreaMessage() = default;
    explicit AreaMessage(const GeoArea& area) { geoBroadcastTo(area); }
    std::string_view typeName() const override { return "Area"; }
    std::size_t byteSize() const override { return 100; }
    std::unique_ptr<V2xMessage> clone() const override { return std::make_unique<AreaMessage>(*this); }
};

/// One that cannot be copied, so cannot be forwarded.
class Uncopyable : public V2xMessage {
public:
    explicit Uncopyable(const GeoArea& area) { geoBroadcastTo(area); }
    std::string_view typeName() const override { return "Uncopyable"; }
    std::size_t byteSize() const override { return 100; }
};

const GeoArea kArea{{500, 0}, 1000};  // x from -500 to 1500 on the road y = 0

Router::Neighbours none() { return {}; }

/// A frame from `source`'s router at `at`.
std::unique_ptr<V2xMessage> originated(Router& source, const V& at, const GeoArea& area = kArea,
                                       const Router::Neighbours& neighbours = none()) {
    auto m = std::make_unique<AreaMessage>(area);
    source.originate(*m, at, neighbours);
    return m;
}

TEST(CbfTimeout, EndpointsExact) {
    const CbfTimeout cbf;
    EXPECT_EQ(cbf(0), ms(100)) << "TO_CBF_MAX at the forwarder itself";
    EXPECT_EQ(cbf(1000), ms(1)) << "TO_CBF_MIN at DIST_MAX";
}

TEST(CbfTimeout, FallsLinearlyInBetween) {
    const CbfTimeout cbf;
    EXPECT_EQ(cbf(500), ms(50.5));
    EXPECT_EQ(cbf(250), ms(75.25));
    EXPECT_EQ(cbf(900), ms(10.9));
    // Equal steps in distance, equal steps in time: 24.75 ms per 250 m.
    for (double d = 0; d < 1000; d += 250) EXPECT_EQ(cbf(d) - cbf(d + 250), ms(24.75)) << d;
    EXPECT_LT(cbf(300.001), cbf(300)) << "strictly falling";
}

TEST(CbfTimeout, ClampedOutsideZeroToDistMax) {
    const CbfTimeout cbf;
    EXPECT_EQ(cbf(1000.5), ms(1));
    EXPECT_EQ(cbf(5000), ms(1));
    EXPECT_EQ(cbf(-20), ms(100));
    EXPECT_EQ(cbf(std::numeric_limits<double>::quiet_NaN()), ms(100)) << "no distance known: the longest wait";
    const CbfTimeout custom{ms(2), ms(50), 400};
    EXPECT_EQ(custom(0), ms(50));
    EXPECT_EQ(custom(200), ms(26));
    EXPECT_EQ(custom(400), ms(2));
    EXPECT_EQ(custom(900), ms(2));
}

TEST(DuplicatePacketList, BySourceAndSequenceNumber) {
    DuplicatePacketList dpl;
    EXPECT_FALSE(dpl.seen({"a", 7}));
    EXPECT_TRUE(dpl.seen({"a", 7}));
    EXPECT_TRUE(dpl.contains({"a", 7}));
    EXPECT_FALSE(dpl.seen({"b", 7})) << "another source's packet with the same number";
    EXPECT_FALSE(dpl.seen({"a", 8}));
    EXPECT_TRUE(dpl.seen({"b", 7}));
}

TEST(DuplicatePacketList, KeepsTheLastEightOfASource) {
    DuplicatePacketList dpl;
    for (std::uint16_t n = 0; n < DuplicatePacketList::kLength; ++n) EXPECT_FALSE(dpl.seen({"a", n}));
    for (std::uint16_t n = 0; n < DuplicatePacketList::kLength; ++n) EXPECT_TRUE(dpl.contains({"a", n}));
    EXPECT_FALSE(dpl.seen({"a", 100}));
    EXPECT_FALSE(dpl.contains({"a", 0})) << "the oldest went";
    EXPECT_TRUE(dpl.contains({"a", 1}));
}

TEST(Router, SourceStampsItsPackets) {
    Router s("s", {.forwarding = true, .hopLimit = 10, .cbf = {}});
    auto first = originated(s, V(0, 0));
    auto second = originated(s, V(10, 0));
    const PacketHeader& h = first->geonet();
    EXPECT_TRUE(h.geoBroadcast());
    EXPECT_EQ(h.source, "s");
    EXPECT_EQ(h.sequence, 0);
    EXPECT_EQ(second->geonet().sequence, 1);
    EXPECT_EQ(h.maxHopLimit, 10);
    EXPECT_EQ(h.hopLimit, 10);
    EXPECT_EQ(h.hops(), 1u);
    EXPECT_EQ(h.senderPosition, V(0, 0));
    EXPECT_TRUE(h.nextHop.empty()) << "inside its area: a broadcast";
    // A single-hop broadcast stays one: no source, never forwarded, always passed up.
    AreaMessage shb;
    s.originate(shb, V(0, 0), none());
    EXPECT_FALSE(shb.geonet().geoBroadcast());
    EXPECT_TRUE(shb.geonet().source.empty());
    Router r("r");
    const auto got = r.receive(shb, V(9000, 0), SimTime::zero(), none());
    EXPECT_TRUE(got.passUp);
    EXPECT_EQ(r.contending(), 0u);
}

TEST(Router, InsideTheAreaPassesUpOnceAndContends) {
    Router s("s"), a("a");
    auto frame = originated(s, V(0, 0));
    const SimTime now = SimTime::fromSeconds(3);
    const auto got = a.receive(*frame, V(300, 0), now, none());
    EXPECT_TRUE(got.passUp);
    EXPECT_FALSE(got.forwardNow) << "inside the area: buffered, not sent at once";
    EXPECT_TRUE(got.timersChanged);
    EXPECT_TRUE(a.contending(frame->geonet().id()));
    EXPECT_EQ(a.nextTimeout(), now + CbfTimeout{}(300));
    // The same frame again (heard twice): not passed up again, and it cancels the contention.
    const auto again = a.receive(*frame, V(300, 0), now, none());
    EXPECT_FALSE(again.passUp);
    EXPECT_EQ(a.contending(), 0u);
}

TEST(Router, TheFarthestReceiverFiresFirstWithOneHopLess) {
    Router s("s"), near("near"), far("far");
    auto frame = originated(s, V(0, 0));
    const SimTime now = SimTime::fromSeconds(1);
    (void)near.receive(*frame, V(100, 0), now, none());
    (void)far.receive(*frame, V(450, 0), now, none());
    ASSERT_TRUE(far.nextTimeout() && near.nextTimeout());
    EXPECT_LT(*far.nextTimeout(), *near.nextTimeout());
    EXPECT_TRUE(far.takeExpired(*far.nextTimeout() - SimTime::fromNanoseconds(1), V(450, 0)).empty());
    auto fired = far.takeExpired(*far.nextTimeout(), V(452, 0));
    ASSERT_EQ(fired.size(), 1u);
    const PacketHeader& h = fired[0]->geonet();
    EXPECT_EQ(h.source, "s") << "the source stays";
    EXPECT_EQ(h.sequence, frame->geonet().sequence);
    EXPECT_EQ(h.hopLimit, 9);
    EXPECT_EQ(h.hops(), 2u);
    EXPECT_EQ(h.senderPosition, V(452, 0)) << "the forwarder's position when it sends";
    EXPECT_EQ(far.contending(), 0u);
    EXPECT_FALSE(far.nextTimeout());
    EXPECT_EQ(fired[0]->typeName(), "Area") << "a copy of the message itself";
}

TEST(Router, ADuplicateBeforeTheTimeoutCancels) {
    Router s("s"), near("near"), far("far");
    auto frame = originated(s, V(0, 0));
    const SimTime now = SimTime::fromSeconds(1);
    EXPECT_TRUE(near.receive(*frame, V(100, 0), now, none()).passUp);
    (void)far.receive(*frame, V(450, 0), now, none());
    const SimTime farFires = *far.nextTimeout();
    auto forwarded = far.takeExpired(farFires, V(450, 0));
    ASSERT_EQ(forwarded.size(), 1u);
    // `near` hears far's rebroadcast while its own timer still runs: it gives up.
    ASSERT_LT(farFires, *near.nextTimeout());
    const auto heard = near.receive(*forwarded[0], V(100, 0), farFires, none());
    EXPECT_FALSE(heard.passUp) << "passed up once only";
    EXPECT_FALSE(heard.forwardNow);
    EXPECT_TRUE(heard.timersChanged);
    EXPECT_EQ(near.contending(), 0u);
    EXPECT_FALSE(near.nextTimeout());
    EXPECT_TRUE(near.takeExpired(SimTime::fromSeconds(10), V(100, 0)).empty()) << "nothing left to send";
}

TEST(Router, ADuplicateAfterTheTimeoutDoesNotForwardAgain) {
    Router s("s"), a("a"), b("b");
    auto frame = originated(s, V(0, 0));
    const SimTime now = SimTime::fromSeconds(1);
    (void)a.receive(*frame, V(400, 0), now, none());
    (void)b.receive(*frame, V(400, 1), now, none());
    auto fromA = a.takeExpired(*a.nextTimeout(), V(400, 0));
    auto fromB = b.takeExpired(*b.nextTimeout(), V(400, 1));  // the same timeout: both sent
    ASSERT_EQ(fromA.size(), 1u);
    ASSERT_EQ(fromB.size(), 1u);
    // Each then hears the other's rebroadcast, and the source hears both: no one forwards again.
    const std::vector<std::pair<Router*, const V2xMessage*>> hearings{
        {&a, fromB[0].get()}, {&b, fromA[0].get()}, {&s, fromA[0].get()}};
    for (const auto& [router, frameHeard] : hearings) {
        const auto heard = router->receive(*frameHeard, V(400, 0), now + ms(200), none());
        EXPECT_FALSE(heard.passUp);
        EXPECT_FALSE(heard.forwardNow);
        EXPECT_FALSE(heard.timersChanged);
        EXPECT_EQ(router->contending(), 0u);
    }
}

TEST(Router, HopLimitStopsForwarding) {
    Router s("s", {.forwarding = true, .hopLimit = 2, .cbf = {}});
    Router a("a"), c("c");
    auto frame = originated(s, V(0, 0));
    EXPECT_EQ(frame->geonet().hopLimit, 2);
    const SimTime now = SimTime::fromSeconds(1);
    (void)a.receive(*frame, V(400, 0), now, none());
    auto second = a.takeExpired(*a.nextTimeout(), V(400, 0));
    ASSERT_EQ(second.size(), 1u);
    EXPECT_EQ(second[0]->geonet().hopLimit, 1);
    EXPECT_EQ(second[0]->geonet().hops(), 2u);
    // The second hop reaches `c` with no hop left: passed up, not forwarded.
    const auto atC = c.receive(*second[0], V(800, 0), now + ms(100), none());
    EXPECT_TRUE(atC.passUp);
    EXPECT_FALSE(atC.forwardNow);
    EXPECT_EQ(c.contending(), 0u);
    // A hop limit of 1: nobody forwards the first transmission.
    Router single("single", {.forwarding = true, .hopLimit = 1, .cbf = {}});
    auto once = originated(single, V(0, 0));
    Router d("d");
    EXPECT_TRUE(d.receive(*once, V(300, 0), now, none()).passUp);
    EXPECT_EQ(d.contending(), 0u);
    EXPECT_THROW(Router("bad", {.forwarding = true, .hopLimit = 0, .cbf = {}}), std::invalid_argument);
}

TEST(Router, AMessageThatCannotBeCopiedIsPassedUpButNotForwarded) {
    Router s("s"), a("a");
    Uncopyable m(kArea);
    s.originate(m, V(0, 0), none());
    const auto got = a.receive(m, V(300, 0), SimTime::zero(), none());
    EXPECT_TRUE(got.passUp);
    EXPECT_EQ(a.contending(), 0u);
}

TEST(Router, OutsideTheAreaNeitherPassedUpNorForwardedWhenSentFromInside) {
    Router s("s"), out("out");
    auto frame = originated(s, V(1400, 0));  // inside, near the edge at 1500
    const auto got = out.receive(*frame, V(1700, 0), SimTime::zero(), [] {
        return std::vector<Neighbour>{{"closer", V(1600, 0)}};
    });
    EXPECT_FALSE(got.passUp);
    EXPECT_FALSE(got.forwardNow) << "an area broadcast stays in the area";
    EXPECT_EQ(out.contending(), 0u);
}

TEST(Router, ForwardingOffIsOneHop) {
    const RouterSettings off{.forwarding = false, .hopLimit = 10, .cbf = {}};
    Router s("s", off), in("in", off), out("out", off);
    auto frame = originated(s, V(-900, 0), kArea, [] { return std::vector<Neighbour>{{"n", V(-400, 0)}}; });
    EXPECT_EQ(frame->geonet().hopLimit, 1);
    EXPECT_TRUE(frame->geonet().nextHop.empty()) << "no greedy forwarding: a broadcast";
    EXPECT_TRUE(in.receive(*frame, V(-300, 0), SimTime::zero(), none()).passUp);
    EXPECT_TRUE(in.receive(*frame, V(-300, 0), SimTime::zero(), none()).passUp) << "no duplicate detection either";
    EXPECT_FALSE(out.receive(*frame, V(-700, 0), SimTime::zero(), none()).passUp);
    EXPECT_EQ(in.contending(), 0u);
}

TEST(GreedyForwarding, MostProgressTowardsTheTarget) {
    const V target(1000, 0);
    const std::vector<Neighbour> around{
        {"behind", V(-200, 0)}, {"side", V(0, 300)}, {"ahead", V(350, 10)}, {"best", V(420, -30)}};
    EXPECT_EQ(greedyNextHop(V(0, 0), target, around), 3u);
    EXPECT_EQ(greedyNextHop(V(500, 0), target, around), std::nullopt) << "a local optimum: nobody is nearer";
    EXPECT_EQ(greedyNextHop(V(0, 0), target, {}), std::nullopt);
    const std::vector<Neighbour> tie{{"a", V(300, 40)}, {"b", V(300, -40)}};
    EXPECT_EQ(greedyNextHop(V(0, 0), target, tie), 0u) << "ties: the first given";
}

TEST(Router, GreedyStepFromOutsideTheArea) {
    const GeoArea area{{2000, 0}, 300};  // x from 1700 to 2300
    Router s("s");
    const auto around = [] {
        return std::vector<Neighbour>{{"back", V(-300, 0)}, {"mid", V(250, 0)}, {"front", V(480, 5)}};
    };
    auto frame = originated(s, V(0, 0), area, around);
    EXPECT_EQ(frame->geonet().nextHop, "front") << "unicast to the neighbour with the most progress";
    EXPECT_EQ(frame->geonet().hops(), 1u);

    // Stations the frame is not addressed to drop it, and may still take the packet later.
    Router mid("mid");
    EXPECT_FALSE(mid.receive(*frame, V(250, 0), SimTime::zero(), none()).passUp);
    EXPECT_FALSE(mid.receive(*frame, V(250, 0), SimTime::zero(), none()).forwardNow);

    // The next hop, still outside, takes the next greedy step at once.
    Router front("front");
    auto step = front.receive(*frame, V(480, 5), SimTime::zero(), [] {
        return std::vector<Neighbour>{{"s", V(0, 0)}, {"further", V(950, 0)}};
    });
    EXPECT_FALSE(step.passUp) << "outside the area";
    ASSERT_TRUE(step.forwardNow);
    const PacketHeader& h = step.forwardNow->geonet();
    EXPECT_EQ(h.nextHop, "further");
    EXPECT_EQ(h.hops(), 2u);
    EXPECT_EQ(h.source, "s");
    EXPECT_EQ(h.senderPosition, V(480, 5));
    EXPECT_EQ(front.contending(), 0u);

    // Inside the area only the addressed station takes it: it passes it up and contends
    // (broadcasting it there).
    Router inside("inside");
    const auto in = inside.receive(*step.forwardNow, V(1750, 0), SimTime::zero(), none());
    EXPECT_FALSE(in.passUp) << "addressed to 'further', not to it";
    EXPECT_EQ(inside.contending(), 0u);
    Router further("further");
    const auto atFurther = further.receive(*step.forwardNow, V(1750, 0), SimTime::zero(), none());
    EXPECT_TRUE(atFurther.passUp);
    EXPECT_EQ(further.contending(), 1u);
    auto broadcast = further.takeExpired(*further.nextTimeout(), V(1750, 0));
    ASSERT_EQ(broadcast.size(), 1u);
    EXPECT_TRUE(broadcast[0]->geonet().nextHop.empty()) << "inside the area: a broadcast again";
}

TEST(Router, ALocalOptimumBroadcasts) {
    const GeoArea area{{2000, 0}, 300};
    Router s("s");
    auto frame = originated(s, V(0, 0), area, [] { return std::vector<Neighbour>{{"back", V(-300, 0)}}; });
    EXPECT_TRUE(frame->geonet().nextHop.empty())
        << "no neighbour with progress: broadcast (the standard without store-carry-forward)";
    // A station outside hearing that broadcast from outside tries the next greedy step.
    Router back("back");
    auto step = back.receive(*frame, V(-300, 0), SimTime::zero(), [] {
        return std::vector<Neighbour>{{"s", V(0, 0)}};
    });
    ASSERT_TRUE(step.forwardNow);
    EXPECT_EQ(step.forwardNow->geonet().nextHop, "s");
    // ... which the source, having sent it, takes for the duplicate it is.
    const auto atSource = s.receive(*step.forwardNow, V(0, 0), SimTime::zero(), none());
    EXPECT_FALSE(atSource.passUp);
    EXPECT_FALSE(atSource.forwardNow);
}

}  // namespace
}  // namespace sbsim::radio::geonet
