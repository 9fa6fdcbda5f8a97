// Services that name the message types they take (IndicatedTypes, as Artery's ports): such a
// service's indicate() gets only those types; a station whose services all name theirs is visited
// only by those types' messages; the others are still
// received (counted per type); a service without the mix-in makes its station take everything; CAMs
// still reach a restricted station's LDM, and geo-broadcasts its router; a station's types follow its
// services when they change.

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "ServicesTestSupport.h"
#include "sbsim/facilities/Cam.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/Receiver.h"
#include "sbsim/radio/disc/DiscMedium.h"
#include "sbsim/services/IndicatedTypes.h"
#include "sbsim/services/ServiceRegistry.h"

namespace sbsim::services::test {
namespace {

/// The probe, taking only the types of its `takes` parameter (comma-separated; empty: none).
class PickyProbe : public ProbeService, public IndicatedTypes {
public:
    std::vector<std::string> indicatedTypes() const override {
        std::vector<std::string> out;
        const std::string list = parameter("takes").value_or("");
        std::size_t from = 0;
        while (from < list.size()) {
            const std::size_t comma = std::min(list.find(',', from), list.size());
            out.push_back(list.substr(from, comma - from));
            from = comma + 1;
        }
        return out;
    }
};
SBSIM_REGISTER_SERVICE(PickyProbe);

/// A test message geo-broadcast to `area` (forwarded: it clones).
class AreaMessage : public TestMessage {
public:
    explicit AreaMessage(const radio::geonet::GeoArea& area) : TestMessage("Geo", 1) { geoBroadcastTo(area); }
    std::unique_ptr<radio::V2xMessage> clone() const override { return std::make_unique<AreaMessage>(*this); }
};

constexpr std::string_view kServices = R"(<services>
    <service type="PickyProbe" takes="Ping"><filters><name pattern="ping.*"/></filters></service>
    <service type="PickyProbe" takes=""><filters><name pattern="deaf.*"/></filters></service>
    <service type="PickyProbe" takes="Pong"><filters><name pattern="mixed.*"/></filters></service>
    <service type="TestProbe"><filters><name pattern="(mixed|s|all).*"/></filters></service>
</services>)";

radio::DiscSettings disc(double range) {
    radio::DiscSettings s;
    s.range = range;
    s.latency = SimTime::fromMilliseconds(1);
    return s;
}

std::vector<std::string> typesHeard(const Harness& h, const std::string& vehicle, const std::string& service) {
    std::vector<std::string> out;
    const ProbeRecord* r = h.log.find(vehicle, service);
    if (r == nullptr) return {"no " + service + " on " + vehicle};
    for (const Indication& i : r->indications) out.push_back(i.type);
    return out;
}

TEST(IndicatedTypes, AStationIsVisitedOnlyByTheTypesItsServicesTake) {
    Harness h(kServices, disc(100));
    h.step(secs(1), {vehicle("s"), vehicle("ping1", 10, 0), vehicle("deaf1", 20, 0), vehicle("mixed1", 30, 0),
                     vehicle("all1", 40, 0)});
    h.at(secs(1), [&] {
        for (const char* type : {"Ping", "Pong", "Other"})
            h.log.probe("s").sendNow(std::make_unique<TestMessage>(type, 0));
    });
    h.sim.run(secs(2));
    using V = std::vector<std::string>;
    EXPECT_EQ(typesHeard(h, "ping1", "PickyProbe"), (V{"Ping"}));
    EXPECT_EQ(typesHeard(h, "deaf1", "PickyProbe"), V{});
    // A service taking every type beside it: the station takes everything, each service its types.
    EXPECT_EQ(typesHeard(h, "mixed1", "TestProbe"), (V{"Ping", "Pong", "Other"}));
    EXPECT_EQ(typesHeard(h, "mixed1", "PickyProbe"), (V{"Pong"}));
    EXPECT_EQ(typesHeard(h, "all1", "TestProbe"), (V{"Ping", "Pong", "Other"}));
    // Received all the same: the counts are the medium's, not the services'.
    for (const char* type : {"Ping", "Pong", "Other"}) EXPECT_EQ(h.medium.counts().at(type).delivered, 4u) << type;
}

TEST(IndicatedTypes, CamsStillReachTheLdmAndGeoBroadcastsTheRouter) {
    // deaf1 and deaf2 take no type. s reaches deaf1 (300 m), not deaf2 (600 m); deaf1 reaches both.
    Harness h(kServices, disc(500));
    h.step(secs(1), {vehicle("s"), vehicle("deaf1", 300, 0), vehicle("deaf2", 600, 0)});
    h.at(secs(1), [&] {
        facilities::CamContent content;
        content.station = "s";
        content.generationTime = secs(1);
        h.log.probe("s").sendNow(std::make_unique<facilities::Cam>(content));
        // A geo-broadcast over all three: only deaf1's router can carry it on to deaf2.
        h.log.probe("s").sendNow(std::make_unique<AreaMessage>(radio::geonet::GeoArea{{300, 0}, 350}));
    });
    bool inLdm = false;
    h.at(secs(1.05), [&] {
        inLdm = h.manager.stations().of(h.manager.middlewareOf("deaf1")->stationIndex()).ldm.find("s") != nullptr;
    });
    h.sim.run(secs(3));
    EXPECT_TRUE(inLdm) << "the station's facilities take CAMs whatever its services take";
    EXPECT_EQ(typesHeard(h, "deaf1", "PickyProbe"), std::vector<std::string>{}) << "its service takes neither";
    // deaf1's router carries it on (to s and deaf2), then deaf2's, inside the area too (to deaf1).
    EXPECT_EQ(h.medium.counts().at("Geo").forwarded, 2u) << "the routers of stations that take no type";
    EXPECT_EQ(h.medium.counts().at("Geo").delivered, 4u);
}

TEST(IndicatedTypes, AStationsTypesFollowItsServices) {
    // ping1 takes Ping; it leaves, and a vehicle of its name comes back with a new middleware.
    constexpr std::string_view services = R"(<services>
        <service type="PickyProbe" takes="Ping"><filters><name pattern="ping.*"/></filters></service>
        <service type="TestProbe"><filters><name pattern="s"/></filters></service>
    </services>)";
    Harness h(services, disc(100));
    h.step(secs(1), {vehicle("s"), vehicle("ping1", 10, 0)});
    h.at(secs(1), [&] { h.log.probe("s").sendNow(std::make_unique<TestMessage>("Pong", 1)); });
    h.step(secs(2), {vehicle("s")});
    h.step(secs(3), {vehicle("s"), vehicle("ping1", 10, 0)});
    h.at(secs(3), [&] {
        h.log.probe("s").sendNow(std::make_unique<TestMessage>("Ping", 2));
        h.log.probe("s").sendNow(std::make_unique<TestMessage>("Pong", 3));
    });
    h.sim.run(secs(4));
    const std::vector<ProbeRecord*> records = h.log.of("ping1");
    ASSERT_EQ(records.size(), 2u);
    EXPECT_TRUE(records[0]->indications.empty());
    ASSERT_EQ(records[1]->indications.size(), 1u);
    EXPECT_EQ(records[1]->indications[0].type, "Ping");
    EXPECT_EQ(h.medium.counts().at("Pong").delivered, 2u);
}

/// A station's receiving side that notes every message it is handed.
struct CountingStation : kernel::Module, radio::Receiver {
    explicit CountingStation(std::string name) : kernel::Module(std::move(name)) {}
    void receive(const radio::V2xMessage& message) override { got.emplace_back(message.typeName()); }
    std::vector<std::string> got;
};

/// A type every station's own layers take (Medium::setLayersTake), as the facilities take CAMs.
class LayerMessage : public TestMessage {
public:
    LayerMessage() : TestMessage("Layer", 0) {}
};

TEST(MediumTypesTaken, AStationIsHandedOnlyItsTypesTheLayersAndGeoBroadcasts) {
    for (const bool layersKnown : {true, false}) {
        SCOPED_TRACE(layersKnown ? "layers known" : "no layers predicate: every station takes everything");
        kernel::Simulation sim;
        VehicleSnapshot snapshot;
        snapshot.assign({vehicle("s"), vehicle("all", 10, 0), vehicle("ping", 20, 0), vehicle("none", 30, 0)}, secs(1));
        std::map<std::string, CountingStation*> stations;
        for (const char* id : {"s", "all", "ping", "none"}) stations[id] = &sim.emplaceModule<CountingStation>(id);
        auto& medium = sim.emplaceModule<radio::DiscMedium>(disc(100), snapshot, [&](const std::string& id) {
            const auto it = stations.find(id);
            return it == stations.end() ? nullptr : static_cast<kernel::Module*>(it->second);
        });
        auto& script = sim.emplaceModule<Script>();
        if (layersKnown) {
            medium.setLayersTake(
                [](const radio::V2xMessage& m) { return dynamic_cast<const LayerMessage*>(&m) != nullptr; });
        }
        medium.setTypesTaken("ping", std::vector<std::string>{"Ping"});
        medium.setTypesTaken("none", std::vector<std::string>{});
        medium.setTypesTaken("all", std::vector<std::string>{"Ping"});
        medium.setTypesTaken("all", std::nullopt);  // the last word counts
        script.at(secs(1), [&] {
            medium.broadcast("s", std::make_unique<TestMessage>("Ping", 0));
            medium.broadcast("s", std::make_unique<TestMessage>("Pong", 0));
            medium.broadcast("s", std::make_unique<LayerMessage>());
            medium.broadcast("s", std::make_unique<AreaMessage>(radio::geonet::GeoArea{{0, 0}, 100}));
        });
        sim.run(secs(2));
        using V = std::vector<std::string>;
        const V every{"Ping", "Pong", "Layer", "Geo"};
        EXPECT_EQ(stations["all"]->got, every);
        EXPECT_EQ(stations["ping"]->got, layersKnown ? (V{"Ping", "Layer", "Geo"}) : every);
        EXPECT_EQ(stations["none"]->got, layersKnown ? (V{"Layer", "Geo"}) : every);
        EXPECT_TRUE(stations["s"]->got.empty());
        for (const char* type : {"Ping", "Pong", "Layer", "Geo"}) EXPECT_EQ(medium.counts().at(type).delivered, 3u);
    }
}

TEST(MediumTypesTaken, AReceiverThatNeverSaidWhatItTakesTakesEverything) {
    // Every registered station is restricted and none takes Pong: a frame of it visits nobody, unless
    // some receiver never registered ("plain").
    for (const bool withPlain : {false, true}) {
        SCOPED_TRACE(withPlain ? "with an unregistered receiver" : "every receiver registered");
        kernel::Simulation sim;
        VehicleSnapshot snapshot;
        std::vector<VehicleSnapshot::Vehicle> vehicles{vehicle("s"), vehicle("ping", 10, 0), vehicle("none", 20, 0)};
        if (withPlain) vehicles.push_back(vehicle("plain", 30, 0));
        snapshot.assign(std::move(vehicles), secs(1));
        std::map<std::string, CountingStation*> stations;
        for (const char* id : {"s", "ping", "none", "plain"}) stations[id] = &sim.emplaceModule<CountingStation>(id);
        auto& medium = sim.emplaceModule<radio::DiscMedium>(disc(100), snapshot, [&](const std::string& id) {
            const auto it = stations.find(id);
            return it == stations.end() ? nullptr : static_cast<kernel::Module*>(it->second);
        });
        auto& script = sim.emplaceModule<Script>();
        medium.setLayersTake([](const radio::V2xMessage&) { return false; });
        medium.setTypesTaken("s", std::vector<std::string>{});
        medium.setTypesTaken("ping", std::vector<std::string>{"Ping"});
        medium.setTypesTaken("none", std::vector<std::string>{});
        script.at(secs(1), [&] {
            medium.broadcast("s", std::make_unique<TestMessage>("Pong", 0));
            medium.broadcast("s", std::make_unique<TestMessage>("Ping", 0));
            medium.broadcast("ping", std::make_unique<TestMessage>("Pong", 1));
        });
        sim.run(secs(2));
        using V = std::vector<std::string>;
        EXPECT_EQ(stations["ping"]->got, V{"Ping"});
        EXPECT_TRUE(stations["none"]->got.empty());
        EXPECT_TRUE(stations["s"]->got.empty());
        EXPECT_EQ(stations["plain"]->got, withPlain ? (V{"Pong", "Ping", "Pong"}) : V{});
        EXPECT_EQ(medium.counts().at("Pong").delivered, withPlain ? 6u : 4u);
    }
}

}  // namespace
}  // namespace sbsim::services::test
