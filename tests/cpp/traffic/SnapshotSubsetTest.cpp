#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::traffic {
namespace {

using Vehicle = VehicleSnapshot::Vehicle;

VehicleSnapshot threeCars() {
    std::vector<Vehicle> cars(3);
    for (int k = 0; k < 3; ++k) {
        cars[k].id = "c" + std::to_string(k);
        cars[k].x = 10.0 * k;
        cars[k].y = -k;
        cars[k].speed = 1.0 + k;
        cars[k].angle = 90.0 * k;
        cars[k].acceleration = -0.5 * k;
        cars[k].length = 4.0 + k;
        cars[k].width = 2.0 + k;
        cars[k].maxSpeed = 30.0 + k;
        cars[k].road = k == 1 ? "r1" : "r0";
        cars[k].lane = cars[k].road + "_0";
        cars[k].type = k == 2 ? "truck" : "car";
    }
    VehicleSnapshot s;
    s.assign(cars, kernel::SimTime::fromSeconds(7));
    return s;
}

TEST(SnapshotSubset, KeepsTheChosenVehiclesWithEveryColumnAndKey) {
    const VehicleSnapshot all = threeCars();
    VehicleSnapshot some;
    some.assignSubset(all, {0, 2});
    ASSERT_EQ(some.size(), 2);
    EXPECT_EQ(some.time(), all.time());
    EXPECT_EQ(some.ids(), (std::vector<std::string>{"c0", "c2"}));
    for (VehicleSnapshot::Index k = 0; k < 2; ++k) {
        const VehicleSnapshot::Index i = k == 0 ? 0 : 2;
        EXPECT_EQ(some.positions().col(k), all.positions().col(i));
        EXPECT_EQ(some.speeds()[k], all.speeds()[i]);
        EXPECT_EQ(some.angles()[k], all.angles()[i]);
        EXPECT_EQ(some.accelerations()[k], all.accelerations()[i]);
        EXPECT_EQ(some.lengths()[k], all.lengths()[i]);
        EXPECT_EQ(some.widths()[k], all.widths()[i]);
        EXPECT_EQ(some.maxSpeeds()[k], all.maxSpeeds()[i]);
        EXPECT_EQ(some.roadId(k), all.roadId(i));
        EXPECT_EQ(some.laneId(k), all.laneId(i));
        EXPECT_EQ(some.typeId(k), all.typeId(i));
        EXPECT_EQ(some.typeKey(k), all.typeKey(i));  // the same interned keys
    }
    EXPECT_EQ(some.internGeneration(), all.internGeneration());
    EXPECT_EQ(some.indexOf("c2"), 1);
    EXPECT_FALSE(some.indexOf("c1"));
    some.assignSubset(all, {});
    EXPECT_TRUE(some.empty());
}

TEST(SnapshotSubset, IndicesMustBeAscendingAndInside) {
    const VehicleSnapshot all = threeCars();
    VehicleSnapshot some;
    EXPECT_THROW(some.assignSubset(all, {2, 1}), std::invalid_argument);
    EXPECT_THROW(some.assignSubset(all, {0, 3}), std::invalid_argument);
    EXPECT_THROW(some.assignSubset(all, {-1}), std::invalid_argument);
    VehicleSnapshot self = threeCars();
    EXPECT_THROW(self.assignSubset(self, {0}), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::traffic
