#include "sbsim/traffic/PairSweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <utility>

#include "TestScenes.h"

namespace sbsim::traffic {
namespace {

using test::car;
using test::randomVehicles;
using test::Vehicle;
using Index = PairSweep::Index;
using Pairs = std::vector<std::pair<Index, Index>>;

/// Every pair (smaller index first) within `radius`, by NeighbourGrid's test, ascending.
Pairs bruteForce(const VehicleSnapshot& s, double radius) {
    Pairs out;
    for (Index i = 0; i < s.size(); ++i) {
        for (Index j = i + 1; j < s.size(); ++j) {
            const double dx = s.positions()(0, j) - s.positions()(0, i);
            const double dy = s.positions()(1, j) - s.positions()(1, i);
            if (dx * dx + dy * dy <= radius * radius) out.emplace_back(i, j);
        }
    }
    return out;
}

/// The sweep's pairs (smaller index first), ascending, each as often as it was visited.
Pairs swept(const PairSweep& sweep) {
    Pairs out;
    sweep.forEachPair([&](Index a, Index b) { out.emplace_back(std::min(a, b), std::max(a, b)); });
    std::sort(out.begin(), out.end());
    return out;
}

/// The sweep visits exactly the brute force's pairs, each once and never a vehicle with itself,
/// and the rows together are the whole sweep. Returns how many pairs there were.
std::size_t expectSameAsBruteForce(const VehicleSnapshot& s, double radius) {
    PairSweep sweep;
    sweep.build(s, radius);
    const Pairs expected = bruteForce(s, radius);
    const Pairs got = swept(sweep);
    EXPECT_EQ(got, expected) << "radius " << radius << ", " << s.size() << " vehicles";
    for (const auto& [a, b] : got) EXPECT_NE(a, b);
    Pairs byRow;
    for (std::size_t row = 0; row < sweep.rows(); ++row) {
        sweep.forEachPairInRow(row, [&](Index a, Index b) { byRow.emplace_back(std::min(a, b), std::max(a, b)); });
    }
    std::sort(byRow.begin(), byRow.end());
    EXPECT_EQ(byRow, expected) << "radius " << radius;
    return expected.size();
}

TEST(PairSweep, MatchesBruteForceOnRandomPositions) {
    std::mt19937_64 rng(20261126);
    VehicleSnapshot s;
    s.assign(randomVehicles(rng, 1500, 1000), kernel::SimTime::zero());
    std::size_t found = 0;
    for (const double radius : {0.0, 7.5, 30.0, 50.0, 120.0, 3000.0}) found += expectSameAsBruteForce(s, radius);
    EXPECT_GT(found, 10'000u);  // not vacuous
}

TEST(PairSweep, MatchesBruteForceOnLatticeWithExactDistances) {
    // Radii that are lattice distances (10, 50 = 30-40-50) put pairs exactly on the radius and
    // vehicles exactly on cell borders; several vehicles share a point (radius 0).
    std::mt19937_64 rng(7);
    for (const double lattice : {10.0, 5.0, 1.0}) {
        VehicleSnapshot s;
        s.assign(randomVehicles(rng, 800, 200, lattice), kernel::SimTime::zero());
        std::size_t found = 0;
        for (const double radius : {0.0, 10.0, 25.0, 50.0}) found += expectSameAsBruteForce(s, radius);
        EXPECT_GT(found, 1000u);
    }
}

TEST(PairSweep, MatchesBruteForceOnARoadGridLikeTheBench) {
    // Vehicles on the lines of a 200 m road grid, as on the bench networks: dense rows, empty cells between.
    std::mt19937_64 rng(28);
    std::uniform_real_distribution<double> along(0, 2000);
    std::uniform_int_distribution<int> road(0, 10);
    std::uniform_real_distribution<double> lane(-4.8, 4.8);
    std::vector<Vehicle> vehicles;
    for (int k = 0; k < 2000; ++k) {
        const double a = along(rng);
        const double b = 200.0 * road(rng) + lane(rng);
        vehicles.push_back(k % 2 == 0 ? car("v" + std::to_string(k), a, b) : car("v" + std::to_string(k), b, a));
    }
    VehicleSnapshot s;
    s.assign(vehicles, kernel::SimTime::zero());
    for (const double radius : {30.0, 50.0, 100.0}) EXPECT_GT(expectSameAsBruteForce(s, radius), 1000u);
}

TEST(PairSweep, MatchesBruteForceWhenSpreadFarApartOrStray) {
    // Clusters tens of kilometres apart (far more cells than vehicles: sorted, not counted), one
    // vehicle at SUMO's "invalid" position, positions that are not finite, and coordinates so
    // large that every pair is tested.
    std::vector<Vehicle> vehicles = test::clustersFarApart();
    VehicleSnapshot clustered;
    clustered.assign(vehicles, kernel::SimTime::zero());
    for (const double radius : {5.0, 20.0, 60.0}) EXPECT_GT(expectSameAsBruteForce(clustered, radius), 100u);

    vehicles.push_back(car("stray", -1073741824.0, -1073741824.0));
    vehicles.push_back(car("stray2", -1073741824.0, -1073741820.0));
    const double inf = std::numeric_limits<double>::infinity();
    vehicles.push_back(car("nan", std::nan(""), 3e5));
    vehicles.push_back(car("inf", inf, -inf));
    vehicles.push_back(car("inf2", inf, -inf));
    VehicleSnapshot stray;
    stray.assign(vehicles, kernel::SimTime::zero());
    for (const double radius : {5.0, 20.0}) EXPECT_GT(expectSameAsBruteForce(stray, radius), 100u);

    std::mt19937_64 rng(99);
    std::vector<Vehicle> huge = randomVehicles(rng, 300, 100);
    huge.push_back(car("far", 4e15, 4e15));
    huge.push_back(car("far2", 4e15 + 8, 4e15));  // 8 m apart: one ulp at 4e15 is 0.5 m
    VehicleSnapshot far;
    far.assign(huge, kernel::SimTime::zero());
    EXPECT_GT(expectSameAsBruteForce(far, 10.0), 100u);
}

TEST(PairSweep, SmallCases) {
    VehicleSnapshot s;
    s.assign({}, kernel::SimTime::zero());
    PairSweep sweep;
    sweep.build(s, 10);
    EXPECT_EQ(sweep.rows(), 0u);
    EXPECT_TRUE(swept(sweep).empty());
    s.assign({car("a", 1, 1)}, kernel::SimTime::fromSeconds(1));
    sweep.build(s, 10);
    EXPECT_TRUE(swept(sweep).empty());
    // Inclusive: 3-4-5 at exactly 5 m, and two vehicles on one point at radius 0.
    s.assign({car("a", 0, 0), car("b", 3, 4), car("c", 0, 0), car("d", -6, -8)}, kernel::SimTime::fromSeconds(2));
    sweep.build(s, 5);
    EXPECT_EQ(swept(sweep), (Pairs{{0, 1}, {0, 2}, {1, 2}}));
    sweep.build(s, 4.999);
    EXPECT_EQ(swept(sweep), (Pairs{{0, 2}}));
    sweep.build(s, 0);
    EXPECT_EQ(swept(sweep), (Pairs{{0, 2}}));
    sweep.build(s, 10);
    EXPECT_EQ(swept(sweep), (Pairs{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {2, 3}}));
}

TEST(PairSweep, RejectsABadRadius) {
    VehicleSnapshot s;
    PairSweep sweep;
    EXPECT_THROW(sweep.build(s, -1), std::invalid_argument);
    EXPECT_THROW(sweep.build(s, std::numeric_limits<double>::infinity()), std::invalid_argument);
    EXPECT_THROW(sweep.build(s, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::traffic
