// Roadside units on hand-made steps: the services file's <rsu> elements (a position, or the POIs
// of a type), RsuCaService's CAMs every second to the vehicles in range and not beyond, vehicles'
// CAMs in the unit's local dynamic map, RsuDenService's DENM from `from` to `until` at its
// interval inside its area, its cancellation, its renewal when the validity runs out, and the
// services file's errors.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ServicesTestSupport.h"
#include "sbsim/facilities/Cam.h"
#include "sbsim/facilities/Denm.h"
#include "sbsim/services/Middleware.h"
#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/ca/RsuCaService.h"
#include "sbsim/services/den/RsuDenService.h"

namespace sbsim::services::test {
namespace {

struct Phases : facilities::DenmPhaseSink {
    std::vector<std::string> lines;
    void denmPhase(const facilities::DenmPhaseEvent& e) override {
        lines.push_back(e.station + " " + std::string(facilities::phaseName(e.phase)) + "@" + e.time.str() + " " +
                        e.action.str());
    }
};

/// Every message a station's RsuProbe service got: (receiver, type, sender, time).
struct Heard {
    std::string station, type, sender;
    SimTime at;
};
std::vector<Heard> heardLog;

class RsuProbe : public Service {
public:
    void indicate(const radio::V2xMessage& m) override {
        heardLog.push_back({vehicleId(), std::string(m.typeName()), m.sender(), simTime()});
    }
};
SBSIM_REGISTER_SERVICE(RsuProbe);

/// The times `station` got a message of `type` from `sender`.
std::vector<SimTime> heard(const Harness&, const std::string& station, const std::string& type,
                           const std::string& sender) {
    std::vector<SimTime> out;
    for (const Heard& h : heardLog) {
        if (h.station == station && h.type == type && h.sender == sender) out.push_back(h.at);
    }
    return out;
}

class RoadsideUnit : public ::testing::Test {
protected:
    void SetUp() override { heardLog.clear(); }
};

/// When station `id`, present from 0 s, first triggers (its own clock, 0.1 s interval).
SimTime firstTrigger(const Harness& h, const std::string& id) { return triggerFrom(h, id, SimTime::zero()); }

radio::DiscSettings range(double metres) {
    radio::DiscSettings s;
    s.range = metres;
    return s;
}

TEST_F(RoadsideUnit, RsuCamsEverySecondReachVehiclesInRangeOnly) {
    Harness h(R"(<services>
        <service type="RsuProbe"/>
        <service type="CaService"/>
        <rsu id="rsu0" x="0" y="0"><service type="artery.application.RsuCaService"/></rsu>
    </services>)",
              range(500));
    h.step(secs(0), {vehicle("near", 300, 0), vehicle("far", 600, 0)});
    h.sim.run(secs(3.05));
    EXPECT_EQ(h.manager.roadsideUnits(), 1u);
    EXPECT_EQ(h.manager.middlewares(), 2u) << "vehicles only";
    // The unit's first trigger (its own clock's phase), then every second, heard a millisecond later.
    const SimTime ms = SimTime::fromMilliseconds(1);
    const std::vector<SimTime> unitCams = every(firstTrigger(h, "rsu0") + ms, secs(1), secs(3.05));
    EXPECT_EQ(heard(h, "near", "CAM", "rsu0"), unitCams);
    EXPECT_TRUE(heard(h, "far", "CAM", "rsu0").empty()) << "600 m: out of range";
    const auto* entry = h.manager.stations().find("near")->ldm.find("rsu0");
    ASSERT_NE(entry, nullptr);
    EXPECT_EQ(entry->cam.stationType, facilities::StationType::RoadSideUnit);
    EXPECT_EQ(entry->cam.position, Eigen::Vector2d(0, 0));
    EXPECT_EQ(entry->cam.speed, 0.0);
    EXPECT_EQ(h.manager.stations().find("far")->ldm.find("rsu0"), nullptr);
    // The unit hears the vehicles' CAMs like any station.
    const auto* unit = h.manager.stations().find("rsu0");
    ASSERT_NE(unit, nullptr);
    EXPECT_NE(unit->ldm.find("near"), nullptr);
    EXPECT_EQ(unit->ldm.find("far"), nullptr);
    const auto& counts = h.medium.counts().at("CAM");
    // The unit's, and one a second from each standing vehicle from its first trigger.
    EXPECT_EQ(counts.sent, unitCams.size() + every(firstTrigger(h, "near"), secs(1), secs(3.05)).size() +
                               every(firstTrigger(h, "far"), secs(1), secs(3.05)).size());
    EXPECT_EQ(facilities::Cam(entry->cam).byteSize(), facilities::Cam::kRoadSideUnitBytes);
}

TEST_F(RoadsideUnit, GenerationIntervalIsArterysParameter) {
    Harness h(R"(<services><service type="RsuProbe"/>
        <rsu id="r" x="0" y="0"><service type="RsuCaService" generationInterval="0.5"/></rsu></services>)");
    h.step(secs(0), {vehicle("v", 10, 0)});
    h.sim.run(secs(1.65));
    EXPECT_EQ(heard(h, "v", "CAM", "r"),
              every(firstTrigger(h, "r") + SimTime::fromMilliseconds(1), secs(0.5), secs(1.65)));
}

TEST_F(RoadsideUnit, DenmRepeatedFromUntilInsideItsAreaThenCancelled) {
    Harness h(R"(<services>
        <service type="RsuProbe"/>
        <rsu id="rsu0" x="0" y="0">
            <service type="RsuDenService" cause="3" subcause="4" from="2" until="6.5" interval="1" area="400"/>
        </rsu>
    </services>)",
              range(500));
    Phases phases;
    h.manager.stations().setPhaseSink(&phases);
    h.step(secs(0), {vehicle("inside", 300, 0), vehicle("outside", 450, 0)});
    std::size_t heldAt4 = 0;
    h.at(secs(4), [&] { heldAt4 = h.manager.stations().find("inside")->denms.size(); });
    h.sim.run(secs(10));
    // 2, 3, 4, 5, 6 s, then the cancellation at 6.5 s.
    EXPECT_EQ(heard(h, "inside", "DENM", "rsu0"),
              (std::vector<SimTime>{secs(2.001), secs(3.001), secs(4.001), secs(5.001), secs(6.001), secs(6.501)}));
    EXPECT_TRUE(heard(h, "outside", "DENM", "rsu0").empty()) << "in radio range, outside the destination area";
    EXPECT_EQ(heldAt4, 1u);
    EXPECT_EQ(h.manager.stations().find("inside")->denms.size(), 0u) << "cancelled";
    EXPECT_EQ(phases.lines, (std::vector<std::string>{"rsu0 new@2 rsu0:1", "inside new@2.001 rsu0:1",
                                                      "rsu0 terminate@6.5 rsu0:1", "inside terminate@6.501 rsu0:1"}));
}

TEST_F(RoadsideUnit, DenmRenewedWhenItsValidityRunsOut) {
    Harness h(R"(<services><service type="RsuProbe"/>
        <rsu id="r" x="0" y="0"><service type="RsuDenService" cause="2" validity="2" x="50" y="0"/></rsu>
    </services>)");
    Phases phases;
    h.manager.stations().setPhaseSink(&phases);
    h.step(secs(0), {vehicle("v", 10, 0)});
    const facilities::DenmMemory::Entry* kept = nullptr;
    SimTime detection;
    h.at(secs(4.5), [&] {
        const auto& memory = h.manager.stations().find("v")->denms;
        if (memory.size() == 1) kept = &memory.entries().begin()->second;
        if (kept != nullptr) detection = kept->denm.detectionTime;
    });
    h.sim.run(secs(5.05));
    EXPECT_EQ(heard(h, "v", "DENM", "r").size(), 6u) << "0, 1, 2, 3, 4, 5 s";
    ASSERT_NE(kept, nullptr) << "the receiver keeps the event across its renewals";
    EXPECT_EQ(detection, secs(4));
    EXPECT_EQ(phases.lines, (std::vector<std::string>{"r new@0 r:1", "v new@0.001 r:1", "r update@2 r:1",
                                                      "v update@2.001 r:1", "r update@4 r:1", "v update@4.001 r:1"}));
}

TEST_F(RoadsideUnit, OneUnitPerPoiOfTheType) {
    Harness h(R"(<services><rsu poiType="rsu"><service type="RsuCaService"/></rsu></services>)");
    h.manager.setPoiSource([] {
        return std::vector<traffic::SumoPois::Poi>{
            {"p1", "rsu", {10, 0}}, {"p2", "tree", {0, 0}}, {"p3", "rsu", {900, 5}}};
    });
    h.sim.run(secs(0.5));
    EXPECT_EQ(h.manager.roadsideUnits(), 2u);
    EXPECT_EQ(h.medium.fixedStations().ids(), (std::vector<std::string>{"p1", "p3"}));
    EXPECT_EQ(h.medium.fixedStations().positions().col(1), Eigen::Vector2d(900, 5));
    EXPECT_EQ(h.medium.counts().at("CAM").sent, 2u);
}

TEST_F(RoadsideUnit, NoPoiOfTheTypeIsAnError) {
    Harness h(R"(<services><rsu poiType="rsu"><service type="RsuCaService"/></rsu></services>)");
    h.manager.setPoiSource([] { return std::vector<traffic::SumoPois::Poi>{{"p2", "tree", {0, 0}}}; });
    try {
        h.sim.run(secs(0.5));
        FAIL() << "no error";
    } catch (const ServicesConfigError& e) {
        EXPECT_STREQ(e.what(), "test.xml:1: <rsu poiType=\"rsu\">: SUMO has no POI of that type (its POI types: tree)");
    }
}

TEST_F(RoadsideUnit, AVehicleServiceOnAUnitIsAnError) {
    Harness h(R"(<services><rsu id="u" x="0" y="0">
                     <service type="artery.application.CaService"/></rsu></services>)");
    try {
        h.sim.run(secs(0.5));
        FAIL() << "no error";
    } catch (const ServicesConfigError& e) {
        EXPECT_STREQ(e.what(),
                     "test.xml:2: CaService cannot run on roadside unit 'u': its CAMs describe its "
                     "vehicle's motion (a unit sends CAMs with RsuCaService)");
    }
}

TEST_F(RoadsideUnit, AVehicleWithAUnitsIdIsAnError) {
    Harness h(R"(<services><service type="RsuProbe"/>
        <rsu id="v" x="0" y="0"><service type="RsuCaService"/></rsu></services>)");
    h.step(secs(1), {vehicle("v", 10, 0)});
    try {
        h.sim.run(secs(2));
        FAIL() << "no error";
    } catch (const ServicesConfigError& e) {
        EXPECT_STREQ(e.what(), "test.xml:2: roadside unit 'v' has the id of a vehicle departing at t=1 s");
    }
}

std::string parseError(std::string_view xml) {
    try {
        (void)ServicesConfig::parse(xml, "s.xml");
    } catch (const ServicesConfigError& e) {
        return e.what();
    }
    return "no error";
}

TEST_F(RoadsideUnit, ServicesFileForms) {
    const ServicesConfig config = ServicesConfig::parse(R"(<services>
        <service type="CaService"/>
        <rsu id="a" x="1.5" y="-2"><service type="RsuCaService"/><service type="RsuDenService" cause="3"/></rsu>
        <rsu poiType="rsu"><service type="RsuCaService" generationInterval="0.5"/></rsu>
    </services>)",
                                                        "s.xml");
    ASSERT_EQ(config.services().size(), 1u);
    ASSERT_EQ(config.roadsideUnits().size(), 2u);
    const RoadsideUnitSpec& a = config.roadsideUnits()[0];
    EXPECT_EQ(a.id, "a");
    EXPECT_EQ(a.x, 1.5);
    EXPECT_EQ(a.y, -2.0);
    ASSERT_EQ(a.services.size(), 2u);
    EXPECT_EQ(a.services[1].type, "RsuDenService");
    EXPECT_EQ(config.roadsideUnits()[1].poiType, "rsu");
    EXPECT_TRUE(config.roadsideUnits()[1].id.empty());

    EXPECT_EQ(parseError(R"(<services><rsu id="a" x="1"><service type="RsuCaService"/></rsu></services>)"),
              "s.xml:1: an <rsu> needs 'id', 'x' and 'y' (or 'poiType' for every SUMO POI of that type)");
    EXPECT_EQ(parseError(R"(<services><rsu id="a" x="1" y="oops"><service type="RsuCaService"/></rsu></services>)"),
              "s.xml:1: attribute 'y' of <rsu> must be a number from -1e+07 to 1e+07 m, got 'oops'");
    // Issue 29: a unit 1e300 m away was taken silently.
    EXPECT_EQ(parseError(R"(<services><rsu id="a" x="1e300" y="0"><service type="RsuCaService"/></rsu></services>)"),
              "s.xml:1: attribute 'x' of <rsu> must be a number from -1e+07 to 1e+07 m, got '1e300'");
    EXPECT_EQ(parseError(R"(<services><rsu poiType="rsu" id="a"><service type="RsuCaService"/></rsu></services>)"),
              "s.xml:1: an <rsu> with 'poiType' takes its id and position from each POI: no id, x or y");
    EXPECT_EQ(parseError(R"(<services><rsu id="a" x="0" y="0"/></services>)"), "s.xml:1: <rsu> has no <service>");
    EXPECT_EQ(parseError(R"(<services><rsu id="a" x="0" y="0"><filters/></rsu></services>)"),
              "s.xml:1: unexpected element <filters> in <rsu> (expected <service>)");
    EXPECT_EQ(
        parseError(
            R"(<services><rsu id="a" x="0" y="0"><service type="RsuCaService"><filters><name pattern="x"/></filters></service></rsu></services>)"),
        "s.xml:1: a roadside unit's <service> takes no <filters>: it runs on the unit");
    EXPECT_EQ(parseError(R"(<services>
        <rsu id="a" x="0" y="0"><service type="RsuCaService"/></rsu>
        <rsu id="a" x="5" y="0"><service type="RsuCaService"/></rsu></services>)"),
              "s.xml:3: two roadside units are called 'a'");
    EXPECT_EQ(parseError(R"(<services><rsu id="a" x="0" y="0" z="1"><service type="RsuCaService"/></rsu></services>)"),
              "s.xml:1: unexpected attribute 'z' on <rsu> (expected id, x and y, or poiType)");
}

TEST_F(RoadsideUnit, RsuDenServiceNeedsACause) {
    Harness h(R"(<services><rsu id="r" x="0" y="0"><service type="RsuDenService"/></rsu></services>)");
    EXPECT_THROW(h.sim.run(secs(1)), ServicesConfigError);
}

}  // namespace
}  // namespace sbsim::services::test
