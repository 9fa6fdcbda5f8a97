// The V2X conditions on a station registry filled by hand: DenmCondition by cause and age of the
// last reception, yielding the running originators (plainly true when none runs), false after
// expiry or termination, filtered by the event's distance, direction and relevance area;
// CamCondition by distance to the known station's CAM position and age; EquippedCondition by the
// run's penetration draw.

#include <gtest/gtest.h>

#include <memory>

#include "StoryboardTestSupport.h"
#include "TestPrinters.h"
#include "sbsim/facilities/Cam.h"
#include "sbsim/facilities/Denm.h"
#include "sbsim/facilities/StationRegistry.h"
#include "sbsim/storyboard/conditions/CamCondition.h"
#include "sbsim/storyboard/conditions/DenmCondition.h"
#include "sbsim/storyboard/conditions/EquippedCondition.h"
#include "sbsim/traffic/Penetration.h"

namespace sbsim::storyboard::test {
namespace {

SimTime secs(double s) { return SimTime::fromSeconds(s); }

facilities::DenmContent event(const std::string& station, int cause, double at, double validity = 600) {
    facilities::DenmContent d;
    d.action = {station, 1};
    d.detectionTime = d.referenceTime = secs(at);
    d.cause = cause;
    d.validity = secs(validity);
    return d;
}

std::vector<VehicleIndex> others(const Scene& scene, std::initializer_list<const char*> ids) {
    std::vector<VehicleIndex> out;
    for (const char* id : ids) out.push_back(scene.index(id));
    return out;
}

TEST(DenmCondition, MatchesCauseAndAgeAndYieldsTheOriginators) {
    auto stations = std::make_shared<facilities::StationRegistry>();
    stations->of("w").denms.received(event("crash", 2, 10), secs(10.001));
    stations->of("w").denms.received(event("rsu", 2, 11), secs(11.001));  // not a vehicle
    stations->of("x").denms.received(event("slip", 6, 10), secs(10.001));
    stations->of("y").denms.received(event("rsu", 2, 11), secs(11.001));
    Scene scene(
        {car("crash", 0, 0), car("slip", 10, 0), car("w", 20, 0), car("x", 30, 0), car("y", 40, 0), car("z", 50, 0)},
        secs(15), 100, stations.get());
    DenmCondition accident(2, std::nullopt);
    EXPECT_EQ(scene.test(accident, "w").others(), others(scene, {"crash"}));
    EXPECT_FALSE(scene.test(accident, "x"));
    EXPECT_TRUE(scene.test(accident, "y"));  // the originator is no running vehicle: plainly true
    EXPECT_FALSE(scene.test(accident, "y").isSet());
    EXPECT_FALSE(scene.test(accident, "z"));  // no station at all
    DenmCondition any(std::nullopt, std::nullopt);
    EXPECT_EQ(scene.test(any, "x").others(), others(scene, {"slip"}));
    // Heard 4.999 s ago at most: w's events (10.001, 11.001) at 15 s.
    DenmCondition recent(2, secs(4));
    // The crash event is 4.999 s old, the roadside unit's 3.999 s: only the latter, plainly true.
    EXPECT_TRUE(scene.test(recent, "w"));
    EXPECT_FALSE(scene.test(recent, "w").isSet());
    EXPECT_TRUE(scene.test(recent, "y"));
    DenmCondition tooRecent(2, secs(3));
    EXPECT_FALSE(scene.test(tooRecent, "w"));
    // A repetition renews the age.
    stations->of("w").denms.received(event("crash", 2, 10), secs(14.5));
    EXPECT_EQ(scene.test(tooRecent, "w").others(), others(scene, {"crash"}));
    EXPECT_EQ(accident.describe(), "DenmCondition(cause 2)");
    EXPECT_EQ(tooRecent.describe(), "DenmCondition(cause 2, max age 3 s)");
    EXPECT_EQ(any.describe(), "DenmCondition(any cause)");
    EXPECT_TRUE(accident.pure());
}

TEST(DenmCondition, FalseOnceTheEventExpiredOrEnded) {
    auto stations = std::make_shared<facilities::StationRegistry>();
    stations->of("w").denms.received(event("crash", 2, 10, 5), secs(10));
    DenmCondition c(2, std::nullopt);
    Scene scene({car("crash", 0, 0), car("w", 20, 0)}, secs(15), 100, stations.get());
    EXPECT_TRUE(scene.test(c, "w"));
    scene.set({car("crash", 0, 0), car("w", 20, 0)}, secs(15.001));
    EXPECT_FALSE(scene.test(c, "w")) << "expired, though not dropped yet";
    auto cancel = event("crash", 2, 10, 5);
    cancel.referenceTime = secs(12);
    cancel.termination = facilities::Termination::Cancellation;
    stations->of("w").denms.received(cancel, secs(12));
    scene.set({car("crash", 0, 0), car("w", 20, 0)}, secs(13));
    EXPECT_FALSE(scene.test(c, "w"));
}

TEST(DenmCondition, RelevanceFiltersTheEventsByDistanceDirectionAndArea) {
    auto stations = std::make_shared<facilities::StationRegistry>();
    auto crash = event("crash", 2, 10);
    crash.eventPosition = {500, 0};
    crash.destination.center = {500, 0};
    crash.destination.radius = 400;
    for (const char* id : {"east", "west", "near", "far"}) stations->of(id).denms.received(crash, secs(10.001));
    // SUMO angles: 90 = driving east (+x), 270 = west.
    Scene scene({car("crash", 500, 0), car("east", 300, 0, 30, 90), car("west", 300, 0, 30, 270),
                 car("near", 450, 0, 30, 90), car("far", 0, 0, 30, 90)},
                secs(12), 100, stations.get());
    DenmRelevance aheadWithin300;
    aheadWithin300.within = 300;
    aheadWithin300.ahead = true;
    DenmCondition warnedAhead(2, std::nullopt, aheadWithin300);
    EXPECT_EQ(scene.test(warnedAhead, "east").others(), others(scene, {"crash"}));
    EXPECT_FALSE(scene.test(warnedAhead, "west")) << "the event is behind it";
    EXPECT_TRUE(scene.test(warnedAhead, "near"));
    EXPECT_FALSE(scene.test(warnedAhead, "far")) << "500 m away";
    DenmRelevance area;
    area.inRelevanceArea = true;
    DenmCondition inArea(2, std::nullopt, area);
    EXPECT_TRUE(scene.test(inArea, "east")) << "inside the 400 m destination circle";
    EXPECT_FALSE(scene.test(inArea, "far"));
    // A relevance distance, when the DENM gives one, is the area.
    crash.relevanceDistance = 100;
    crash.referenceTime = secs(11);
    for (const char* id : {"east", "near"}) stations->of(id).denms.received(crash, secs(11));
    EXPECT_FALSE(scene.test(inArea, "east")) << "200 m from the event, relevance 100 m";
    EXPECT_TRUE(scene.test(inArea, "near"));
    EXPECT_EQ(warnedAhead.describe(), "DenmCondition(cause 2, within 300 m, ahead)");
    EXPECT_EQ(inArea.describe(), "DenmCondition(cause 2, in relevance area)");
    EXPECT_TRUE(warnedAhead.columns().contains(traffic::SnapshotColumns::Angle));
    EXPECT_TRUE(DenmCondition(2, std::nullopt).columns().empty());
}

TEST(CamCondition, KnowsStationsWithinDistanceAndAge) {
    auto stations = std::make_shared<facilities::StationRegistry>();
    const auto cam = [](const std::string& id, double x, double t) {
        facilities::CamContent c;
        c.station = id;
        c.position = {x, 0};
        c.generationTime = secs(t);
        return c;
    };
    stations->of("ego").ldm.update(stations->intern("near"), cam("near", 30, 9.5), secs(9.5));
    stations->of("ego").ldm.update(stations->intern("far"), cam("far", 200, 9.9), secs(9.9));
    stations->of("ego").ldm.update(stations->intern("rsu"), cam("rsu", 10, 9.9), secs(9.9));
    Scene scene({car("ego", 0, 0), car("near", 35, 0), car("far", 205, 0)}, secs(10), 100, stations.get());
    CamCondition within50(50.0, std::nullopt);
    EXPECT_EQ(scene.test(within50, "ego").others(), others(scene, {"near"}));
    CamCondition anywhere(std::nullopt, std::nullopt);
    EXPECT_EQ(scene.test(anywhere, "ego").others(), others(scene, {"far", "near"}));
    CamCondition fresh(50.0, secs(0.2));
    EXPECT_TRUE(scene.test(fresh, "ego"));  // only the roadside unit's CAM is fresh enough
    EXPECT_FALSE(scene.test(fresh, "ego").isSet());
    EXPECT_FALSE(scene.test(anywhere, "near"));
    scene.set({car("ego", 0, 0), car("near", 35, 0), car("far", 205, 0)}, secs(10.8));
    EXPECT_EQ(scene.test(anywhere, "ego").others(), others(scene, {"far"})) << "near's CAM outlived 1.1 s";
    EXPECT_EQ(within50.describe(), "CamCondition(within 50 m)");
    EXPECT_EQ(fresh.describe(), "CamCondition(within 50 m, max age 0.2 s)");
}

TEST(EquippedCondition, IsTheRunsPenetrationDraw) {
    const traffic::Penetration half(0.5, 7);
    // Ids on both sides of the draw, found by the draw itself (Penetration is tested on its own).
    std::vector<std::string> equipped, unequipped;
    for (int k = 0; equipped.size() < 2 || unequipped.size() < 2; ++k) {
        const std::string id = "veh" + std::to_string(k);
        (half.equipped(id) ? equipped : unequipped).push_back(id);
    }
    traffic::VehicleSnapshot snapshot;
    snapshot.assign(
        {car(equipped[0], 0, 0), car(unequipped[0], 10, 0), car(equipped[1], 20, 0), car(unequipped[1], 30, 0)},
        secs(1));
    traffic::NeighbourGrid grid;
    grid.build(snapshot, 100);
    const EvaluationContext ctx(snapshot, grid, nullptr, nullptr, nullptr, &half);
    EquippedCondition c;
    for (const std::string& id : equipped) EXPECT_TRUE(c.test(ctx, *snapshot.indexOf(id))) << id;
    for (const std::string& id : unequipped) EXPECT_FALSE(c.test(ctx, *snapshot.indexOf(id))) << id;
    // No penetration given (the default, 1): everyone carries equipment.
    const EvaluationContext everyone(snapshot, grid);
    for (const std::string& id : unequipped) EXPECT_TRUE(c.test(everyone, *snapshot.indexOf(id))) << id;
    const traffic::Penetration nobody(0.0, 7);
    const EvaluationContext none(snapshot, grid, nullptr, nullptr, nullptr, &nobody);
    for (const std::string& id : equipped) EXPECT_FALSE(c.test(none, *snapshot.indexOf(id))) << id;
    EXPECT_TRUE(c.pure());
    EXPECT_EQ(c.columns(), traffic::SnapshotColumns{});
    EXPECT_EQ(c.describe(), "EquippedCondition()");
}

}  // namespace
}  // namespace sbsim::storyboard::test
