// GeoNetworking in the middleware, on the disc medium and hand-made steps: a geo-broadcast
// travels hop by hop along a line of stations through contention-based forwarding (the CBF timers
// are the middlewares' self-messages), each station inside the area hands it to its services
// exactly once, one outside never; with forwarding off it goes one hop as before.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "ServicesTestSupport.h"
#include "sbsim/radio/disc/DiscMedium.h"
#include "sbsim/radio/geonet/GeoArea.h"
#include "sbsim/services/Middleware.h"

namespace sbsim::services::test {
namespace {

constexpr std::string_view kProbes = R"(<services><service type="TestProbe"/></services>)";

/// A test message geo-broadcast to `area`.
class AreaTestMessage : public TestMessage {
public:
    explicit AreaTestMessage(const radio::geonet::GeoArea& area) : TestMessage("Geo", 0) { geoBroadcastTo(area); }
    std::unique_ptr<radio::V2xMessage> clone() const override { return std::make_unique<AreaTestMessage>(*this); }
};

radio::DiscSettings range(double metres) {
    radio::DiscSettings s;
    s.range = metres;
    return s;
}

/// Stations 400 m apart on a line, a 500 m radio range: each hears only its neighbours. The area
/// (x from -450 to 1250) holds v0 ... v3; v4 at 1,600 m is outside it.
void line(Harness& h) {
    h.step(secs(1), {vehicle("v0", 0, 0), vehicle("v1", 400, 0), vehicle("v2", 800, 0), vehicle("v3", 1200, 0),
                     vehicle("v4", 1600, 0)});
    h.at(secs(1), [&h] {
        h.log.probe("v0").sendNow(std::make_unique<AreaTestMessage>(radio::geonet::GeoArea{{400, 0}, 850}));
    });
}

std::size_t indications(const Harness& h, const std::string& vehicle) {
    return h.log.find(vehicle)->indications.size();
}

TEST(GeoNetworking, AGeoBroadcastCrossesItsAreaHopByHop) {
    Harness h(kProbes, range(500));
    line(h);
    h.sim.run(secs(2));
    EXPECT_EQ(indications(h, "v0"), 0u) << "its own packet, heard back from v1, is a duplicate";
    for (const char* v : {"v1", "v2", "v3"}) ASSERT_EQ(indications(h, v), 1u) << v << ": once, however often heard";
    EXPECT_EQ(indications(h, "v4"), 0u) << "outside the area";
    // Each hop is sent by the station before: v1 after its CBF timeout at 400 m (60.4 ms), ...
    EXPECT_EQ(h.log.find("v1")->indications[0].sender, "v0");
    EXPECT_EQ(h.log.find("v2")->indications[0].sender, "v1");
    EXPECT_EQ(h.log.find("v3")->indications[0].sender, "v2");
    const SimTime hop = SimTime::fromRaw(60'400'000) + SimTime::fromMilliseconds(1);  // timeout + latency
    EXPECT_EQ(h.log.find("v1")->indications[0].at, secs(1.001));
    EXPECT_EQ(h.log.find("v2")->indications[0].at, secs(1.001) + hop);
    EXPECT_EQ(h.log.find("v3")->indications[0].at, secs(1.001) + hop * 2);
    // v1, v2 and v3 each forwarded once (v3's copy reached v4, which dropped it).
    const auto& geo = h.medium.counts().at("Geo");
    EXPECT_EQ(geo.sent, 1u);
    EXPECT_EQ(geo.forwarded, 3u);
    for (const char* v : {"v0", "v1", "v2", "v3", "v4"})
        EXPECT_EQ(h.manager.middlewareOf(v)->router().contending(), 0u) << v;
}

TEST(GeoNetworking, AContenderThatHearsTheForwardGivesUp) {
    Harness h(kProbes, range(500));
    // v1b stands 50 m behind v1: both contend for the hop, v1 (farther from v0) fires first, 4.95 ms
    // earlier, and v1b, hearing it 1 ms later, gives up.
    h.step(secs(1), {vehicle("v0", 0, 0), vehicle("v1", 400, 0), vehicle("v1b", 350, 0), vehicle("v2", 800, 0)});
    h.at(secs(1), [&h] {
        h.log.probe("v0").sendNow(std::make_unique<AreaTestMessage>(radio::geonet::GeoArea{{400, 0}, 850}));
    });
    h.sim.run(secs(2));
    EXPECT_EQ(indications(h, "v1b"), 1u);
    EXPECT_EQ(indications(h, "v2"), 1u);
    EXPECT_EQ(h.log.find("v2")->indications[0].sender, "v1");
    EXPECT_EQ(h.medium.counts().at("Geo").forwarded, 2u) << "v1 and v2; v1b gave up";
}

TEST(GeoNetworking, ForwardingOffGoesOneHop) {
    Harness h(kProbes, range(500));
    h.manager.setGeoNetworking({.forwarding = false, .hopLimit = 10, .cbf = {}});
    line(h);
    h.sim.run(secs(2));
    EXPECT_EQ(indications(h, "v1"), 1u);
    for (const char* v : {"v2", "v3", "v4"}) EXPECT_EQ(indications(h, v), 0u) << v;
    EXPECT_EQ(h.medium.counts().at("Geo").forwarded, 0u);
}

TEST(GeoNetworking, TheHopLimitBoundsTheReach) {
    Harness h(kProbes, range(500));
    h.manager.setGeoNetworking({.forwarding = true, .hopLimit = 2, .cbf = {}});
    line(h);
    h.sim.run(secs(2));
    EXPECT_EQ(indications(h, "v1"), 1u);
    EXPECT_EQ(indications(h, "v2"), 1u) << "the second hop";
    EXPECT_EQ(indications(h, "v3"), 0u) << "a third hop is beyond the limit";
    EXPECT_EQ(h.medium.counts().at("Geo").forwarded, 1u);
}

}  // namespace
}  // namespace sbsim::services::test
