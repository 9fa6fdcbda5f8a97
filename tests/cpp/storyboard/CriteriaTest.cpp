// The built-in criteria over hand-built steps: each passes on one run and fails on another,
// reporting what it saw and what was expected.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include "StoryboardTestSupport.h"
#include "sbsim/facilities/StationRegistry.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/criteria/KeepsLane.h"
#include "sbsim/storyboard/criteria/MaxSpeed.h"
#include "sbsim/storyboard/criteria/NoCollision.h"
#include "sbsim/storyboard/criteria/NoRedLightRunning.h"
#include "sbsim/storyboard/criteria/ReachedRegion.h"
#include "sbsim/storyboard/criteria/StoryActivated.h"
#include "sbsim/storyboard/criteria/WarnedBefore.h"
#include "sbsim/traffic/Penetration.h"
#include "sbsim/traffic/TrafficQueries.h"

namespace sbsim::storyboard::test {
namespace {

/// Collisions as a test sets them, for the step that ends at any time; traffic lights as it sets
/// their links and states.
class CollisionsAsSet : public traffic::TrafficQueries {
public:
    std::optional<Leader> leader(const std::string&, double) override { return std::nullopt; }
    const std::vector<Collision>& collisions(kernel::SimTime) override { return now; }
    std::optional<SignalPassage> signalPassage(const std::string&, const std::string& from,
                                               const std::string& to) override {
        const auto link = signals.passed(from, to);
        if (!link) return std::nullopt;
        return SignalPassage{*link, states.at(link->signal).at(static_cast<std::size_t>(link->index))};
    }
    std::vector<Collision> now;
    traffic::SignalLinks signals;
    std::map<std::string, std::string> states;  // per light
};

Vehicle onLane(std::string id, double x, std::string road, std::string lane, double speed = 10) {
    Vehicle v = car(std::move(id), x, 0, speed);
    v.road = std::move(road);
    v.lane = std::move(lane);
    return v;
}

/// Runs `c` over steps 1 s apart and returns its verdict.
CriterionVerdict over(Criterion& c, const std::vector<std::vector<Vehicle>>& steps,
                      traffic::TrafficQueries* queries = nullptr, const std::vector<StoryPtr>& stories = {},
                      const traffic::Penetration* penetration = nullptr) {
    traffic::VehicleSnapshot snapshot;
    traffic::NeighbourGrid grid;
    for (std::size_t k = 0; k < steps.size(); ++k) {
        snapshot.assign(steps[k], SimTime::fromSeconds(static_cast<double>(k + 1)));
        grid.build(snapshot, 100);
        const EvaluationContext ctx(snapshot, grid, queries, nullptr, nullptr, penetration);
        c.prepare(ctx);
        c.observe(ctx);
    }
    return c.verdict(CriterionRun{stories});
}

TEST(Criteria, NoCollisionFailsNamingTheFirstCollision) {
    CollisionsAsSet queries;
    NoCollision clean;
    EXPECT_TRUE(over(clean, {{car("a", 1)}, {car("a", 1)}}, &queries).passed);
    NoCollision crash;
    queries.now = {{"a", "b"}};
    const CriterionVerdict v = over(crash, {{car("a", 1)}}, &queries);
    EXPECT_FALSE(v.passed);
    EXPECT_EQ(v.actual, "1 collision, first a with b at t=1 s");
    EXPECT_EQ(v.expected, "0 collisions");
    EXPECT_EQ(crash.describe(), "NoCollision()");
}

TEST(Criteria, MaxSpeedFailsNamingTheFastestVehicleOfItsSet) {
    MaxSpeed all(12, VehicleSet{});
    const CriterionVerdict fast = over(all, {{car("a", 10), car("b", 11)}, {car("a", 13.5), car("b", 11)}});
    EXPECT_FALSE(fast.passed);
    EXPECT_EQ(fast.actual, "13.500 m/s (a at t=2 s)");
    EXPECT_EQ(fast.expected, "<= 12 m/s");
    MaxSpeed onlyB(12, VehicleSet({"b"}));
    const CriterionVerdict slow = over(onlyB, {{car("a", 10), car("b", 11)}, {car("a", 13.5), car("b", 11)}});
    EXPECT_TRUE(slow.passed) << slow.actual;
    EXPECT_EQ(onlyB.describe(), "MaxSpeed(12, vehicles=[b])");
    EXPECT_THROW(MaxSpeed(-1, VehicleSet{}), std::invalid_argument);
}

/// A penetration of 0.5 whose draw equips exactly the vehicles of `equipped` among `ids` (the first
/// seed that does; Penetration's draw is tested on its own).
traffic::Penetration equipping(const std::vector<std::string>& ids, const std::set<std::string>& equipped) {
    for (std::uint64_t seed = 0;; ++seed) {
        const traffic::Penetration p(0.5, seed);
        if (std::all_of(ids.begin(), ids.end(),
                        [&](const std::string& id) { return p.equipped(id) == equipped.contains(id); }))
            return p;
    }
}

TEST(Criteria, EquippedOnlyJudgesOnlyTheEquippedVehicles) {
    const traffic::Penetration onlyB = equipping({"a", "b"}, {"b"});
    const std::vector<std::vector<Vehicle>> steps = {{car("a", 10), car("b", 11)}, {car("a", 13.5), car("b", 11)}};
    MaxSpeed equipped(12, VehicleSet({}, true));
    const CriterionVerdict v = over(equipped, steps, nullptr, {}, &onlyB);
    EXPECT_TRUE(v.passed) << v.actual;
    EXPECT_EQ(v.actual, "11.000 m/s (b at t=1 s)");
    EXPECT_EQ(equipped.describe(), "MaxSpeed(12, equipped_only=True)");
    MaxSpeed everyone(12, VehicleSet{});
    EXPECT_FALSE(over(everyone, steps, nullptr, {}, &onlyB).passed) << "a, unequipped, was too fast";
    MaxSpeed named(12, VehicleSet({"a"}, true));
    EXPECT_EQ(over(named, steps, nullptr, {}, &onlyB).actual, "no vehicle seen");
    EXPECT_EQ(named.describe(), "MaxSpeed(12, vehicles=[a], equipped_only=True)");

    // Lane changes of the unequipped are not counted.
    const std::vector<std::vector<Vehicle>> change = {{onLane("a", 0, "r", "r_0"), onLane("b", 0, "r", "r_0")},
                                                      {onLane("a", 1, "r", "r_1"), onLane("b", 1, "r", "r_0")}};
    KeepsLane keeps{VehicleSet({}, true)};
    EXPECT_TRUE(over(keeps, change, nullptr, {}, &onlyB).passed);
    KeepsLane all{VehicleSet{}};
    EXPECT_FALSE(over(all, change, nullptr, {}, &onlyB).passed);
    EXPECT_EQ(keeps.describe(), "KeepsLane(equipped_only=True)");
}

TEST(Criteria, ReachedRegionPassesOnlyWhenInTime) {
    const geometry::Polygon box({{10, -5}, {20, -5}, {20, 5}, {10, 5}});
    const std::vector<std::vector<Vehicle>> drive = {{car("a", 0, 0)}, {car("a", 5, 0)}, {car("a", 15, 0)}};
    ReachedRegion early("a", box, SimTime::fromSeconds(3));
    const CriterionVerdict ok = over(early, drive);
    EXPECT_TRUE(ok.passed);
    EXPECT_EQ(ok.actual, "reached at t=3 s");
    ReachedRegion late("a", box, SimTime::fromSeconds(2));
    const CriterionVerdict v = over(late, drive);
    EXPECT_FALSE(v.passed);
    EXPECT_EQ(v.expected, "in the area by t=2 s");
    ReachedRegion nobody("ghost", box, SimTime::fromSeconds(9));
    EXPECT_EQ(over(nobody, drive).actual, "no vehicle ghost seen");
}

TEST(Criteria, KeepsLaneCountsChangesOnOneRoadOnly) {
    // Onto the next road (and its lane) is no change; a new lane on the same road is.
    KeepsLane keeps{VehicleSet{}};
    const CriterionVerdict ok = over(keeps, {{onLane("a", 0, "e1", "e1_0")}, {onLane("a", 5, "e2", "e2_1")}});
    EXPECT_TRUE(ok.passed) << ok.actual;
    KeepsLane strict{VehicleSet{}};
    const CriterionVerdict v = over(strict, {{onLane("a", 0, "e1", "e1_0")}, {onLane("a", 5, "e1", "e1_1")}});
    EXPECT_FALSE(v.passed);
    EXPECT_EQ(v.actual, "1 lane change, first a from e1_0 to e1_1 at t=2 s");
    KeepsLane others{VehicleSet({"b"})};
    EXPECT_TRUE(over(others, {{onLane("a", 0, "e1", "e1_0")}, {onLane("a", 5, "e1", "e1_1")}}).passed);
    EXPECT_EQ(others.describe(), "KeepsLane(vehicles=[b])");
}

TEST(Criteria, NoRedLightRunningCountsPassagesOfARedStopLine) {
    // Light "J" controls link 0 (north, e1_0 over :J_0_0 to e2_0) and link 1 (e1_1 over :J_1_0
    // then :J_5_0 to e3_0).
    CollisionsAsSet lights;
    lights.signals.add({"J", 0}, "e1_0", {":J_0_0"}, "e2_0");
    lights.signals.add({"J", 1}, "e1_1", {":J_1_0", ":J_5_0"}, "e3_0");
    const auto at = [](std::string id, std::string lane) {
        const std::string road = lane.substr(0, lane.rfind('_'));
        return onLane(std::move(id), 0, road, std::move(lane));
    };
    lights.states["J"] = "Gr";
    NoRedLightRunning green{VehicleSet{}};
    // a passes link 0 on green, then moves on inside the junction and beyond; b waits on red.
    const CriterionVerdict ok = over(
        green,
        {{at("a", "e1_0"), at("b", "e1_1")}, {at("a", ":J_0_0"), at("b", "e1_1")}, {at("a", "e2_0"), at("b", "e1_1")}},
        &lights);
    EXPECT_TRUE(ok.passed) << ok.actual;
    EXPECT_EQ(ok.expected, "0 red-light passages");

    NoRedLightRunning red{VehicleSet{}};
    // b passes link 1 on red onto the junction's second internal lane in one step; c changes to
    // link 1's lane (no passage), then jumps straight onto its target lane.
    const CriterionVerdict v = over(
        red,
        {{at("b", "e1_1"), at("c", "e1_0")}, {at("b", ":J_5_0"), at("c", "e1_1")}, {at("b", "e3_0"), at("c", "e3_0")}},
        &lights);
    EXPECT_FALSE(v.passed);
    EXPECT_EQ(v.actual, "2 red-light passages by 2 vehicles (b, c), first b at J link 1 ('r') at t=2 s");
    NoRedLightRunning onlyA{VehicleSet({"a"})};
    EXPECT_TRUE(over(onlyA, {{at("b", "e1_1")}, {at("b", ":J_1_0")}}, &lights).passed);
    EXPECT_EQ(onlyA.describe(), "NoRedLightRunning(vehicles=[a])");

    // Red-yellow is red too (SUMO stops for it); yellow is not.
    lights.states["J"] = "uy";
    NoRedLightRunning amber{VehicleSet{}};
    EXPECT_FALSE(over(amber, {{at("a", "e1_0")}, {at("a", ":J_0_0")}}, &lights).passed);
    NoRedLightRunning yellow{VehicleSet{}};
    EXPECT_TRUE(over(yellow, {{at("b", "e1_1")}, {at("b", ":J_1_0")}}, &lights).passed);
}

TEST(Criteria, StoryActivatedCountsTheNamedStory) {
    auto story =
        std::make_shared<Story>(std::make_shared<TimeCondition>(SimTime::zero()), std::vector<EffectPtr>{}, "rain");
    story->counters().activated();
    story->counters().activated();
    const std::vector<StoryPtr> stories{story};
    StoryActivated twice("rain", 2);
    EXPECT_TRUE(twice.verdict(CriterionRun{stories}).passed);
    StoryActivated thrice("rain", 3);
    const CriterionVerdict v = thrice.verdict(CriterionRun{stories});
    EXPECT_FALSE(v.passed);
    EXPECT_EQ(v.actual, "2 activations");
    EXPECT_EQ(v.expected, ">= 3 activations");
    EXPECT_EQ(StoryActivated("fog", 1).verdict(CriterionRun{stories}).actual, "no story named fog");
    EXPECT_THROW(StoryActivated("rain", 0), std::invalid_argument);
}

/// A DENM of `cause` from `station`, detected at `at`.
facilities::DenmContent denm(const std::string& station, int cause, double at) {
    facilities::DenmContent d;
    d.action = {station, 1};
    d.detectionTime = d.referenceTime = SimTime::fromSeconds(at);
    d.cause = cause;
    return d;
}

/// Four steps (t = 1..4 s) towards a place at x in [100, 120] on edge "e2": "crash" (which sends
/// the DENM) enters at 3 s, a, b, c and e at 4 s, d is there from the start. a hears the accident
/// DENM (cause 2) at 1.5 s, b at 3.5 s, e only a cause 6 one at 1.5 s; c hears nothing.
CriterionVerdict approach(WarnedBefore& c, const traffic::Penetration* penetration = nullptr) {
    facilities::StationRegistry stations;
    traffic::VehicleSnapshot snapshot;
    traffic::NeighbourGrid grid;
    for (int k = 1; k <= 4; ++k) {
        const SimTime now = SimTime::fromSeconds(k);
        if (k == 2) {
            stations.of("a").denms.received(denm("crash", 2, 1.5), SimTime::fromSeconds(1.5));
            stations.of("e").denms.received(denm("slip", 6, 1.5), SimTime::fromSeconds(1.5));
        }
        if (k == 4) stations.of("b").denms.received(denm("crash", 2, 1.5), SimTime::fromSeconds(3.5));
        const auto at = [&](std::string id, bool there) {
            Vehicle v = onLane(std::move(id), there ? 110 : 50, there ? "e2" : "e1", there ? "e2_0" : "e1_0");
            v.y = 0;
            return v;
        };
        snapshot.assign(
            {at("a", k == 4), at("b", k == 4), at("c", k == 4), at("crash", k >= 3), at("d", true), at("e", k == 4)},
            now);
        grid.build(snapshot, 100);
        const EvaluationContext ctx(snapshot, grid, nullptr, nullptr, &stations, penetration);
        c.prepare(ctx);
        c.observe(ctx);
    }
    return c.verdict(CriterionRun{{}, nullptr, {}});
}

TEST(Criteria, WarnedBeforeJudgesTheVehiclesThatReachedThePlace) {
    const geometry::Polygon box({{100, -5}, {120, -5}, {120, 5}, {100, 5}});
    const SimTime zero = SimTime::zero();
    // crash sent the warning and d started there: neither is judged.
    auto accident = WarnedBefore::inArea(box, 2, zero, zero, std::nullopt);
    const CriterionVerdict v = approach(*accident);
    EXPECT_FALSE(v.passed);
    EXPECT_EQ(v.actual, "2 of 4 vehicles reached it unwarned (c, e), first c at t=4 s, never warned");
    EXPECT_EQ(v.expected, "0 vehicles reached it unwarned (warned >= 0 s before)");
    EXPECT_EQ(accident->describe(), "WarnedBefore(4 points, cause=2, seconds=0)");

    auto anyCause = WarnedBefore::inArea(box, std::nullopt, zero, zero, std::nullopt);
    EXPECT_EQ(approach(*anyCause).actual, "1 of 4 vehicles reached it unwarned (c), first c at t=4 s, never warned");
    // b heard it 0.5 s before it arrived: too late for a 1 s lead.
    auto early = WarnedBefore::inArea(box, std::nullopt, SimTime::fromSeconds(1), zero, std::nullopt);
    EXPECT_EQ(approach(*early).actual,
              "2 of 4 vehicles reached it unwarned (b, c), first b at t=4 s, warned at t=3.5 s");
    // Only those reaching it from 5 s on: nobody.
    auto later = WarnedBefore::inArea(box, 2, zero, SimTime::fromSeconds(5), std::nullopt);
    const CriterionVerdict none = approach(*later);
    EXPECT_TRUE(none.passed);
    EXPECT_EQ(none.actual, "no vehicle reached it");
    // Up to 3 s: crash, its sender, alone.
    auto before = WarnedBefore::inArea(box, 2, zero, zero, SimTime::fromSeconds(3));
    EXPECT_EQ(approach(*before).actual, "no vehicle reached it");

    // The edge, with a and b warned in time.
    auto edge = WarnedBefore::onEdge("e2", std::nullopt, SimTime::fromSeconds(0.5), zero, std::nullopt);
    EXPECT_EQ(edge->describe(), "WarnedBefore(edge e2, seconds=0.5)");
    EXPECT_EQ(approach(*edge).actual, "1 of 4 vehicles reached it unwarned (c), first c at t=4 s, never warned");

    // c, never warned, carries no equipment: with equipped_only it is not judged.
    const traffic::Penetration withoutC = equipping({"a", "b", "c", "e"}, {"a", "b", "e"});
    auto equipped = WarnedBefore::inArea(box, 2, zero, zero, std::nullopt, true);
    EXPECT_EQ(approach(*equipped, &withoutC).actual,
              "1 of 3 vehicles reached it unwarned (e), first e at t=4 s, never warned");
    EXPECT_EQ(equipped->describe(), "WarnedBefore(4 points, cause=2, seconds=0, equipped_only=True)");
    auto judgedAll = WarnedBefore::inArea(box, 2, zero, zero, std::nullopt);
    EXPECT_EQ(approach(*judgedAll, &withoutC).actual,
              "2 of 4 vehicles reached it unwarned (c, e), first c at t=4 s, never warned");

    EXPECT_THROW(WarnedBefore::onEdge("e2", 300, zero, zero, std::nullopt), std::invalid_argument);
    EXPECT_THROW(WarnedBefore::onEdge("e2", 2, SimTime::fromSeconds(-1), zero, std::nullopt), std::invalid_argument);
    EXPECT_THROW(WarnedBefore::onEdge("e2", 2, zero, SimTime::fromSeconds(5), SimTime::fromSeconds(4)),
                 std::invalid_argument);
}

TEST(Criteria, AGivenNameReplacesTheDescription) {
    NoCollision c;
    EXPECT_EQ(c.name(), "NoCollision()");
    c.setName("safe");
    EXPECT_EQ(c.name(), "safe");
}

}  // namespace
}  // namespace sbsim::storyboard::test
