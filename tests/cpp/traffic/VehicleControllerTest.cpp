// VehicleController's commands, observed through the next steps' snapshots.
#include <gtest/gtest.h>
#include <libsumo/Simulation.h>
#include <libsumo/TraCIDefs.h>
#include <libsumo/VehicleType.h>

#include <string>
#include <vector>

#include "SumoTestSupport.h"
#include "TestPrinters.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/traffic/SumoBridge.h"
#include "sbsim/traffic/VehicleController.h"

namespace sbsim::test {
namespace {

using kernel::SimTime;
using traffic::SumoBridge;
using traffic::VehicleController;
using traffic::VehicleSnapshot;

/// Runs the scenario step by step (run(t) up to each step time) so the test can act between steps.
class VehicleControllerTest : public testing::Test {
protected:
    void SetUp() override {
        bridge_ = &sim_.emplaceModule<SumoBridge>(scenarioSettings());
        bridge_->demandColumns(traffic::SnapshotColumns::all());
        bridge_->load();
        sim_.initialize();
    }
    void TearDown() override { sim_.finish(); }

    void step() {
        next_ += bridge_->stepLength();
        ASSERT_EQ(sim_.run(next_), kernel::Simulation::StopReason::TimeLimit);
        ASSERT_EQ(snapshot().time(), next_);
    }
    void stepUntil(double seconds) {
        while (next_ < sec(seconds)) step();
    }
    const VehicleSnapshot& snapshot() const { return bridge_->snapshot(); }

    /// A vehicle that departed in the step just made (a long way ahead of it).
    std::string freshVehicle() {
        const std::vector<std::string> departed = libsumo::Simulation::getDepartedIDList();
        EXPECT_FALSE(departed.empty());
        return departed.empty() ? std::string() : departed.front();
    }
    /// The vehicle's value in the current snapshot; fails the test if it is not running.
    double speedOf(const std::string& id) {
        const auto i = snapshot().indexOf(id);
        EXPECT_TRUE(i.has_value()) << id << " is not running at " << snapshot().time().str() << " s";
        return i ? snapshot().speeds()[*i] : -1;
    }
    double maxSpeedOf(const std::string& id) {
        const auto i = snapshot().indexOf(id);
        EXPECT_TRUE(i.has_value()) << id << " is not running at " << snapshot().time().str() << " s";
        return i ? snapshot().maxSpeeds()[*i] : -1;
    }

    kernel::Simulation sim_;
    SumoBridge* bridge_ = nullptr;
    SimTime next_;
};

TEST_F(VehicleControllerTest, LiveQueriesMatchTheSnapshot) {
    stepUntil(20);
    ASSERT_GT(snapshot().size(), 5);
    for (VehicleSnapshot::Index i = 0; i < snapshot().size(); ++i) {
        VehicleController c(snapshot().ids()[i]);
        EXPECT_EQ(c.id(), snapshot().ids()[i]);
        EXPECT_EQ(c.speed(), snapshot().speeds()[i]);
        EXPECT_EQ(c.maxSpeed(), snapshot().maxSpeeds()[i]);
        EXPECT_EQ(c.typeId(), snapshot().typeId(i));
        EXPECT_EQ(c.roadId(), snapshot().roadId(i));
        EXPECT_EQ(c.laneId(), snapshot().laneId(i));
        // Lane ids end in "_<index>".
        EXPECT_EQ(c.laneId().substr(c.laneId().rfind('_') + 1), std::to_string(c.laneIndex()));
        EXPECT_EQ(c.emergencyDecel(), libsumo::VehicleType::getEmergencyDecel(c.typeId()));
        EXPECT_EQ(c.speedMode(), 31);  // SUMO's default: all checks on
    }
}

TEST_F(VehicleControllerTest, SetMaxSpeedShowsInTheNextSnapshot) {
    stepUntil(10);
    const std::string id = freshVehicle();
    VehicleController c(id, &bridge_->maxSpeedListener());
    const double before = maxSpeedOf(id);
    ASSERT_GT(before, 5.0);
    c.setMaxSpeed(5.0);
    EXPECT_EQ(c.maxSpeed(), 5.0);       // live at once
    EXPECT_EQ(maxSpeedOf(id), before);  // the snapshot is the step's, unchanged until the next
    step();
    EXPECT_EQ(maxSpeedOf(id), 5.0);
    for (int i = 0; i < 5; ++i) step();
    EXPECT_LE(speedOf(id), 5.0);  // it has slowed down to its new cap
}

TEST_F(VehicleControllerTest, SetSpeedZeroStopsAndMinusOneReleases) {
    stepUntil(10);
    const std::string id = freshVehicle();
    VehicleController c(id);
    step();
    ASSERT_GT(speedOf(id), 1.0);
    c.setSpeed(0);
    int stepsToStop = 0;
    while (speedOf(id) > 0 && stepsToStop < 10) {
        step();
        ++stepsToStop;
    }
    EXPECT_EQ(speedOf(id), 0.0);
    EXPECT_LE(stepsToStop, 5);  // ~14 m/s at 4.5 m/s² deceleration
    // It stays put, whatever the traffic lights do.
    const auto i = snapshot().indexOf(id);
    ASSERT_TRUE(i.has_value());
    const Eigen::Vector2d where = snapshot().positions().col(*i);
    for (int k = 0; k < 20; ++k) step();
    EXPECT_EQ(speedOf(id), 0.0);
    EXPECT_EQ(snapshot().positions().col(*snapshot().indexOf(id)), where);

    c.setSpeed(-1);
    int stepsToMove = 0;
    while (speedOf(id) == 0 && stepsToMove < 90) {  // at most a red light's wait
        step();
        ++stepsToMove;
    }
    EXPECT_GT(speedOf(id), 0.0) << "still standing " << stepsToMove << " steps after release";
}

TEST_F(VehicleControllerTest, SlowDownReachesTheTargetSpeed) {
    stepUntil(10);
    const std::string id = freshVehicle();
    VehicleController c(id);
    step();
    ASSERT_GT(speedOf(id), 8.0);
    c.slowDown(3.0, 3.0);
    for (int k = 0; k < 3; ++k) step();
    EXPECT_NEAR(speedOf(id), 3.0, 0.5);
}

TEST_F(VehicleControllerTest, SpeedModeIsSetAndRead) {
    stepUntil(5);
    VehicleController c(freshVehicle());
    c.setSpeedMode(0);
    EXPECT_EQ(c.speedMode(), 0);
    c.setSpeedMode(31);
    EXPECT_EQ(c.speedMode(), 31);
}

TEST_F(VehicleControllerTest, UnknownVehicleThrows) {
    stepUntil(2);
    VehicleController c("no-such-vehicle");
    EXPECT_THROW(c.speed(), libsumo::TraCIException);
    EXPECT_THROW(c.setSpeed(1.0), libsumo::TraCIException);
}

}  // namespace
}  // namespace sbsim::test
