// OpenSCENARIO's RelativeDistanceCondition and TraveledDistanceCondition on hand-made snapshots,
// the distances computed by hand.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "StoryboardTestSupport.h"
#include "sbsim/storyboard/conditions/PositionDistanceCondition.h"
#include "sbsim/storyboard/conditions/RelativeDistanceCondition.h"
#include "sbsim/storyboard/conditions/TraveledDistanceCondition.h"
#include "sbsim/traffic/TrafficQueries.h"

namespace sbsim::storyboard::test {
namespace {

using Kind = RelativeDistanceCondition::Kind;

/// ego drives east (SUMO angle 90), front bumper at (10, 0), 5 m × 2 m: it spans x 5..10, y -1..1,
/// centre (7.5, 0). lead drives east, front at (30, 3), 4 m × 2 m: x 26..30, y 2..4, centre (28, 3).
/// cross drives north (angle 0), front at (30, 5), 4 m × 2 m: x 29..31, y 1..5, centre (30, 3).
Scene& scene() {
    static Scene s({car("ego", 10, 0, 10, 90, 5, 2), car("lead", 30, 3, 10, 90, 4, 2), car("cross", 30, 5, 5, 0, 4, 2),
                    car("beside", 9, 1.5, 10, 90, 5, 2)});
    return s;
}

double measured(Kind kind, bool freespace, const std::string& to = "lead") {
    const RelativeDistanceCondition c(to, 0, ComparisonRule::GreaterOrEqual, kind, freespace);
    return c.distance(scene().snapshot(), scene().index("ego"), scene().index(to));
}

TEST(RelativeDistanceCondition, DistancesByKindBetweenCentresAndOutlines) {
    EXPECT_NEAR(measured(Kind::Longitudinal, false), 20.5, 1e-9);
    EXPECT_NEAR(measured(Kind::Longitudinal, true), 16.0, 1e-9);  // 26 − 10
    EXPECT_NEAR(measured(Kind::Lateral, false), 3.0, 1e-9);
    EXPECT_NEAR(measured(Kind::Lateral, true), 1.0, 1e-9);  // 2 − 1
    EXPECT_NEAR(measured(Kind::Cartesian, false), std::sqrt(20.5 * 20.5 + 9), 1e-9);
    EXPECT_NEAR(measured(Kind::Cartesian, true), std::sqrt(16.0 * 16 + 1), 1e-9);  // corner (10, 1) to (26, 2)
    // A vehicle across the ego's heading: its width lies along it.
    EXPECT_NEAR(measured(Kind::Longitudinal, false, "cross"), 22.5, 1e-9);
    EXPECT_NEAR(measured(Kind::Longitudinal, true, "cross"), 19.0, 1e-9);  // 29 − 10
    EXPECT_NEAR(measured(Kind::Lateral, true, "cross"), 0.0, 1e-9) << "y 1..5 against -1..1: they touch";
    // Overlapping outlines: no free space.
    EXPECT_NEAR(measured(Kind::Cartesian, true, "beside"), 0.0, 1e-9);
    EXPECT_NEAR(measured(Kind::Lateral, false, "beside"), 1.5, 1e-9);
}

double toPoint(const Eigen::Vector2d& point, Kind kind, bool freespace) {
    const PositionDistanceCondition c(point, 0, ComparisonRule::GreaterOrEqual, kind, freespace);
    return c.distance(scene().snapshot(), scene().index("ego"));
}

TEST(PositionDistanceCondition, DistancesToAPointByKindFromTheCentreAndTheOutline) {
    // ego: centre (7.5, 0), outline x 5..10, y -1..1, heading east; the point (20, 3).
    const Eigen::Vector2d p(20, 3);
    EXPECT_NEAR(toPoint(p, Kind::Longitudinal, false), 12.5, 1e-9);
    EXPECT_NEAR(toPoint(p, Kind::Longitudinal, true), 10.0, 1e-9);  // 20 − 10
    EXPECT_NEAR(toPoint(p, Kind::Lateral, false), 3.0, 1e-9);
    EXPECT_NEAR(toPoint(p, Kind::Lateral, true), 2.0, 1e-9);  // 3 − 1
    EXPECT_NEAR(toPoint(p, Kind::Cartesian, false), std::sqrt(12.5 * 12.5 + 9), 1e-9);
    EXPECT_NEAR(toPoint(p, Kind::Cartesian, true), std::sqrt(100.0 + 4), 1e-9);  // from the corner (10, 1)
    // A point on the outline or inside it: no free space.
    for (const Kind k : {Kind::Longitudinal, Kind::Lateral, Kind::Cartesian}) {
        EXPECT_NEAR(toPoint({8, 0.5}, k, true), 0.0, 1e-9);
    }
    const auto holds = [](double value, ComparisonRule rule) {
        PositionDistanceCondition c({20, 3}, value, rule, Kind::Longitudinal, true);  // 10 m
        return static_cast<bool>(scene().test(c, "ego"));
    };
    EXPECT_FALSE(holds(10.0, ComparisonRule::LessThan));
    EXPECT_TRUE(holds(10.0, ComparisonRule::LessOrEqual));
    EXPECT_TRUE(holds(10.005, ComparisonRule::EqualTo)) << "within 0.01 m";
    EXPECT_TRUE(holds(9.0, ComparisonRule::GreaterThan));
    EXPECT_THROW(PositionDistanceCondition({NAN, 0}, 1, ComparisonRule::LessThan, Kind::Lateral, false),
                 std::invalid_argument);
    EXPECT_THROW(PositionDistanceCondition({0, 0}, -1, ComparisonRule::LessThan, Kind::Lateral, false),
                 std::invalid_argument);
}

TEST(RelativeDistanceCondition, RulesYieldTheVehicle) {
    const auto test = [](double value, ComparisonRule rule) {
        RelativeDistanceCondition c("lead", value, rule, Kind::Longitudinal, true);  // 16 m
        return scene().others(scene().test(c, "ego"));
    };
    EXPECT_EQ(test(16.0, ComparisonRule::LessThan), Ids{});
    EXPECT_EQ(test(16.0, ComparisonRule::LessOrEqual), Ids{"lead"});
    EXPECT_EQ(test(16.005, ComparisonRule::EqualTo), Ids{"lead"}) << "within 0.01 m";
    EXPECT_EQ(test(16.02, ComparisonRule::EqualTo), Ids{});
    EXPECT_EQ(test(16.02, ComparisonRule::NotEqualTo), Ids{"lead"});
    EXPECT_EQ(test(15.0, ComparisonRule::GreaterThan), Ids{"lead"});
    EXPECT_EQ(test(16.0, ComparisonRule::GreaterOrEqual), Ids{"lead"});
    RelativeDistanceCondition self("ego", 100, ComparisonRule::LessThan, Kind::Cartesian, false);
    EXPECT_FALSE(scene().test(self, "ego")) << "not to itself";
    RelativeDistanceCondition gone("nobody", 100, ComparisonRule::LessThan, Kind::Cartesian, false);
    EXPECT_FALSE(scene().test(gone, "ego")) << "false while the vehicle does not run";
    EXPECT_TRUE(self.pure());
    EXPECT_THROW(RelativeDistanceCondition("", 1, ComparisonRule::LessThan, Kind::Lateral, false),
                 std::invalid_argument);
    EXPECT_THROW(RelativeDistanceCondition("a", -1, ComparisonRule::LessThan, Kind::Lateral, false),
                 std::invalid_argument);
    EXPECT_EQ(ruleNamed("greaterOrEqual"), ComparisonRule::GreaterOrEqual);
    EXPECT_FALSE(ruleNamed(">=").has_value());
    EXPECT_EQ(RelativeDistanceCondition::kindNamed("lateral"), Kind::Lateral);
}

/// Odometers by vehicle, as SUMO's getDistance would give them.
class Odometers : public traffic::TrafficQueries {
public:
    std::map<std::string, double> driven;
    int asked = 0;
    std::optional<Leader> leader(const std::string&, double) override { return std::nullopt; }
    const std::vector<Collision>& collisions(SimTime) override { return none_; }
    std::optional<SignalPassage> signalPassage(const std::string&, const std::string&, const std::string&) override {
        return std::nullopt;
    }
    double odometer(const std::string& vehicle) override {
        ++asked;
        return driven.at(vehicle);
    }

private:
    std::vector<Collision> none_;
};

TEST(TraveledDistanceCondition, TrueFromTheDistanceOn) {
    traffic::VehicleSnapshot snapshot;
    snapshot.assign({car("a", 1), car("b", 1), car("c", 1)}, SimTime::fromSeconds(1));
    traffic::NeighbourGrid grid;
    grid.build(snapshot, 100);
    Odometers odometers;
    odometers.driven = {{"a", 99.9}, {"b", 100.0}, {"c", 250.0}};
    const EvaluationContext ctx{snapshot, grid, &odometers};
    TraveledDistanceCondition c(100);
    EXPECT_FALSE(c.test(ctx, *snapshot.indexOf("a")));
    EXPECT_TRUE(c.test(ctx, *snapshot.indexOf("b")));
    EXPECT_TRUE(c.test(ctx, *snapshot.indexOf("c")));
    EXPECT_EQ(odometers.asked, 3);
    EXPECT_FALSE(c.pure()) << "it asks SUMO, so only from the board's thread";
    EXPECT_THROW(TraveledDistanceCondition(-1), std::invalid_argument);
    EXPECT_THROW(TraveledDistanceCondition(NAN), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::storyboard::test
