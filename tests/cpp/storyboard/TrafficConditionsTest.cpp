// Conditions that ask the traffic for what the snapshot lacks (leader, collisions), against a
// model of SUMO's answers.

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <stdexcept>

#include "StoryboardTestSupport.h"
#include "sbsim/storyboard/conditions/AllCondition.h"
#include "sbsim/storyboard/conditions/CarSetCondition.h"
#include "sbsim/storyboard/conditions/CollisionCondition.h"
#include "sbsim/storyboard/conditions/HeadwayCondition.h"

namespace sbsim::storyboard::test {
namespace {

/// Answers from tables and records what was asked.
class ModelTraffic : public traffic::TrafficQueries {
public:
    std::map<std::string, Leader> leaders;
    std::vector<Collision> reported;
    std::vector<std::pair<std::string, double>> leaderQueries;
    int collisionQueries = 0;

    std::optional<Leader> leader(const std::string& vehicle, double lookAhead) override {
        leaderQueries.emplace_back(vehicle, lookAhead);
        const auto it = leaders.find(vehicle);
        if (it == leaders.end() || it->second.gap > lookAhead) return std::nullopt;
        return it->second;
    }
    const std::vector<Collision>& collisions(SimTime /*now*/) override {
        ++collisionQueries;
        return reported;
    }
    std::optional<SignalPassage> signalPassage(const std::string&, const std::string&, const std::string&) override {
        return std::nullopt;  // a road without traffic lights
    }
};

/// A snapshot with its grid and a context that queries `traffic`.
struct TrafficScene {
    explicit TrafficScene(std::vector<Vehicle> vehicles) {
        snapshot.assign(std::move(vehicles), SimTime::fromSeconds(1));
        grid.build(snapshot, 100);
    }
    ConditionResult test(Condition& c, std::string_view id) {
        c.prepare(ctx);
        return c.test(ctx, *snapshot.indexOf(id));
    }
    Ids others(const ConditionResult& r) const {
        Ids ids;
        for (const VehicleIndex i : r.others()) ids.push_back(snapshot.ids()[i]);
        return ids;
    }
    ModelTraffic traffic;
    traffic::VehicleSnapshot snapshot;
    traffic::NeighbourGrid grid;
    EvaluationContext ctx{snapshot, grid, &traffic};
};

TEST(HeadwayCondition, YieldsTheLeaderWhenTheTimeGapIsBelowTheThreshold) {
    HeadwayCondition c(2.0);
    TrafficScene scene({car("a", 0, 0, 10), car("b", 0, 0, 10), car("c", 0, 0, 0.05), car("lead", 0, 0, 10)});
    scene.traffic.leaders = {{"a", {"lead", 19.9}}, {"b", {"lead", 20.0}}, {"c", {"lead", 0.1}}};
    const ConditionResult r = scene.test(c, "a");
    EXPECT_EQ(scene.others(r), (Ids{"lead"}));
    EXPECT_FALSE(scene.test(c, "b")) << "2.0 s is not below 2.0 s";
    EXPECT_TRUE(scene.test(c, "b").isSet());
    EXPECT_FALSE(scene.test(c, "lead")) << "no leader";
    const std::size_t asked = scene.traffic.leaderQueries.size();
    EXPECT_FALSE(scene.test(c, "c")) << "a standing ego has no headway";
    EXPECT_EQ(scene.traffic.leaderQueries.size(), asked) << "and SUMO is not asked";
    // Search range: at least 100 m, else speed × seconds × 2.
    EXPECT_DOUBLE_EQ(scene.traffic.leaderQueries.front().second, 100.0);
    HeadwayCondition wide(6.0);
    scene.test(wide, "a");
    EXPECT_DOUBLE_EQ(scene.traffic.leaderQueries.back().second, 120.0);
    EXPECT_FALSE(c.pure()) << "it asks SUMO, so only from the board's thread";
    EXPECT_THROW(HeadwayCondition(0), std::invalid_argument);
}

TEST(HeadwayCondition, OnlyVehiclesReachingItAreQueried) {
    const auto headway = std::make_shared<HeadwayCondition>(2.0);
    AllCondition c({std::make_shared<CarSetCondition>(std::set<std::string>{"a"}), headway});
    TrafficScene scene({car("a", 0, 0, 10), car("b", 0, 0, 10)});
    scene.test(c, "a");
    scene.test(c, "b");
    ASSERT_EQ(scene.traffic.leaderQueries.size(), 1u);
    EXPECT_EQ(scene.traffic.leaderQueries[0].first, "a");
}

TEST(HeadwayCondition, WithoutTrafficToQueryItIsAnError) {
    HeadwayCondition c(2.0);
    Scene scene({car("a", 0, 0, 10)});
    EXPECT_THROW(scene.test(c, "a"), std::logic_error);
}

TEST(CollisionCondition, YieldsTheOtherPartiesAskingOncePerStep) {
    CollisionCondition c;
    TrafficScene scene({car("a", 0, 0), car("b", 0, 0), car("c", 0, 0), car("d", 0, 0)});
    scene.traffic.reported = {{"a", "b"}, {"c", "a"}, {"a", "b"}, {"gone", "d"}};
    EXPECT_EQ(scene.others(scene.test(c, "a")), (Ids{"b", "c"}));
    EXPECT_EQ(scene.others(scene.test(c, "b")), (Ids{"a"}));
    EXPECT_EQ(scene.others(scene.test(c, "c")), (Ids{"a"}));
    EXPECT_FALSE(scene.test(c, "d")) << "a party that is no longer running is left out";
    EXPECT_EQ(scene.traffic.collisionQueries, 1);
    EXPECT_TRUE(c.pure());
}

}  // namespace
}  // namespace sbsim::storyboard::test
