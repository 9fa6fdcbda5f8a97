// VehicleSnapshot::idsVersion(): equal versions promise equal id lists (VehiclePass and
// TtcCondition then keep each vehicle's row at its index instead of matching the ids).

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::traffic {
namespace {

using Vehicle = VehicleSnapshot::Vehicle;

std::vector<Vehicle> cars(const std::vector<std::string>& ids, double speed = 1) {
    std::vector<Vehicle> out;
    for (const std::string& id : ids) {
        Vehicle v;
        v.id = id;
        v.speed = speed;
        out.push_back(v);
    }
    return out;
}

TEST(SnapshotIdsVersion, KeptWhileTheSameVehiclesRunAndNewWhenOneComesOrGoes) {
    VehicleSnapshot s;
    s.assign(cars({"b", "a"}), kernel::SimTime::fromSeconds(1));
    const std::uint64_t first = s.idsVersion();
    s.assign(cars({"a", "b"}, 7), kernel::SimTime::fromSeconds(2));  // other values, same vehicles
    EXPECT_EQ(s.idsVersion(), first);
    s.assign(cars({"a", "b", "c"}), kernel::SimTime::fromSeconds(3));
    const std::uint64_t grown = s.idsVersion();
    EXPECT_NE(grown, first);
    s.assign(cars({"a", "c"}), kernel::SimTime::fromSeconds(4));
    EXPECT_NE(s.idsVersion(), grown);
    EXPECT_NE(s.idsVersion(), first);
    s.assign(cars({"a", "d"}), kernel::SimTime::fromSeconds(5));  // as many, another one
    const std::uint64_t swapped = s.idsVersion();
    s.assign(cars({"a", "b"}), kernel::SimTime::fromSeconds(6));  // the first list again: a new version
    EXPECT_NE(s.idsVersion(), swapped);
    EXPECT_NE(s.idsVersion(), first);
    // A bad list changes nothing.
    const std::uint64_t kept = s.idsVersion();
    EXPECT_THROW(s.assign(cars({"a", "a"}), kernel::SimTime::fromSeconds(7)), std::invalid_argument);
    EXPECT_EQ(s.idsVersion(), kept);
}

TEST(SnapshotIdsVersion, DifferentSnapshotsDifferUnlessCopied) {
    VehicleSnapshot one;
    VehicleSnapshot two;
    one.assign(cars({"a"}), kernel::SimTime::zero());
    two.assign(cars({"b"}), kernel::SimTime::zero());
    EXPECT_NE(one.idsVersion(), two.idsVersion());
    VehicleSnapshot empty;
    EXPECT_NE(empty.idsVersion(), VehicleSnapshot().idsVersion());
    const VehicleSnapshot copy = one;  // the same ids: the same version
    EXPECT_EQ(copy.idsVersion(), one.idsVersion());
}

TEST(SnapshotIdsVersion, ASubsetKeepsItWhileItKeepsTheSameVehicles) {
    VehicleSnapshot all;
    all.assign(cars({"a", "b", "c"}), kernel::SimTime::zero());
    VehicleSnapshot view;
    view.assignSubset(all, {0, 2});
    const std::uint64_t first = view.idsVersion();
    all.assign(cars({"a", "b", "c"}, 5), kernel::SimTime::fromSeconds(1));
    view.assignSubset(all, {0, 2});
    EXPECT_EQ(view.idsVersion(), first);
    view.assignSubset(all, {0, 1});
    EXPECT_NE(view.idsVersion(), first);
    const std::uint64_t second = view.idsVersion();
    // Refused half-way (the ids partly overwritten): a new version all the same.
    EXPECT_THROW(view.assignSubset(all, {2, 1}), std::invalid_argument);
    EXPECT_NE(view.idsVersion(), second);
}

}  // namespace
}  // namespace sbsim::traffic
