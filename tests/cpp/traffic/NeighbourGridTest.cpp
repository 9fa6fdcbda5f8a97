#include "sbsim/traffic/NeighbourGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "TestScenes.h"

namespace sbsim::traffic {
namespace {

using test::car;
using test::randomVehicles;
using test::Vehicle;
using Index = NeighbourGrid::Index;

std::vector<Index> bruteForce(const VehicleSnapshot& s, Index i, double radius) {
    std::vector<Index> out;
    for (Index j = 0; j < s.size(); ++j) {
        const double dx = s.positions()(0, j) - s.positions()(0, i);
        const double dy = s.positions()(1, j) - s.positions()(1, i);
        if (j != i && dx * dx + dy * dy <= radius * radius) out.push_back(j);
    }
    return out;
}

void expectSameAsBruteForce(const VehicleSnapshot& s, const NeighbourGrid& grid, double radius) {
    for (Index i = 0; i < s.size(); ++i) {
        const std::vector<Index> expected = bruteForce(s, i, radius);
        ASSERT_EQ(grid.within(i, radius), expected) << "vehicle " << i << ", radius " << radius;
        // forEachWithin visits the same vehicles, each once.
        std::vector<Index> visited;
        grid.forEachWithin(i, radius, [&](Index j) { visited.push_back(j); });
        std::sort(visited.begin(), visited.end());
        ASSERT_EQ(visited, expected) << "vehicle " << i << ", radius " << radius;
    }
}

TEST(NeighbourGrid, MatchesBruteForceOnRandomPositions) {
    std::mt19937_64 rng(20240601);
    VehicleSnapshot s;
    s.assign(randomVehicles(rng, 1500, 1000), kernel::SimTime::zero());
    NeighbourGrid grid;
    grid.build(s, 50);
    EXPECT_EQ(grid.cellSize(), 50);
    std::size_t found = 0;
    for (const double radius : {0.0, 7.5, 50.0, 120.0, 3000.0}) {
        expectSameAsBruteForce(s, grid, radius);
        found += grid.within(0, radius).size();
    }
    EXPECT_GT(found, 1500u);  // the comparison is not vacuous
}

TEST(NeighbourGrid, MatchesBruteForceOnLatticeWithExactDistances) {
    std::mt19937_64 rng(7);
    VehicleSnapshot s;
    s.assign(randomVehicles(rng, 800, 200, 10), kernel::SimTime::zero());
    for (const double cellSize : {10.0, 25.0, 50.0}) {
        NeighbourGrid grid;
        grid.build(s, cellSize);
        for (const double radius : {0.0, 10.0, 50.0}) expectSameAsBruteForce(s, grid, radius);
    }
}

TEST(NeighbourGrid, MatchesBruteForceWhenSpreadFarApartAndClustered) {
    VehicleSnapshot s;
    s.assign(test::clustersFarApart(), kernel::SimTime::zero());
    NeighbourGrid grid;
    grid.build(s, 20);
    for (const double radius : {5.0, 20.0, 60.0}) expectSameAsBruteForce(s, grid, radius);
}

TEST(NeighbourGrid, MatchesBruteForceWithOneStrayFarOffPosition) {
    // A compact scene (one bucket per cell) turned sparse by one vehicle at SUMO's "invalid"
    // position, as libsumo reports for a vehicle off the road: both layouts give the same answers.
    std::mt19937_64 rng(5);
    std::vector<Vehicle> vehicles = randomVehicles(rng, 400, 300);
    VehicleSnapshot compact;
    compact.assign(vehicles, kernel::SimTime::zero());
    vehicles.push_back(car("stray", -1073741824.0, -1073741824.0));
    VehicleSnapshot sparse;
    sparse.assign(vehicles, kernel::SimTime::zero());
    for (const VehicleSnapshot* s : {&compact, &sparse}) {
        NeighbourGrid grid;
        grid.build(*s, 25);
        for (const double radius : {10.0, 25.0, 80.0}) expectSameAsBruteForce(*s, grid, radius);
    }
}

TEST(NeighbourGrid, DistanceIsInclusiveAndExcludesTheVehicleItself) {
    VehicleSnapshot s;
    s.assign({car("a", 0, 0), car("b", 3, 4), car("c", 0, 0), car("d", -6, -8)}, kernel::SimTime::zero());
    NeighbourGrid grid;
    grid.build(s, 5);
    EXPECT_EQ(grid.within(0, 5), (std::vector<Index>{1, 2}));
    EXPECT_EQ(grid.within(0, 4.999), (std::vector<Index>{2}));
    EXPECT_EQ(grid.within(0, 0), (std::vector<Index>{2}));  // same position
    EXPECT_EQ(grid.within(0, 10), (std::vector<Index>{1, 2, 3}));
    EXPECT_EQ(grid.within(1, 15), (std::vector<Index>{0, 2, 3}));
    EXPECT_EQ(grid.within(1, 14.999), (std::vector<Index>{0, 2}));
    EXPECT_TRUE(grid.within(0, -1).empty());
}

TEST(NeighbourGrid, AroundAPointMatchesBruteForceInBothLayouts) {
    // A roadside unit's neighbours: every vehicle within the radius of a place, none skipped.
    std::mt19937_64 rng(77);
    std::vector<Vehicle> vehicles = randomVehicles(rng, 500, 400);
    VehicleSnapshot compact;
    compact.assign(vehicles, kernel::SimTime::zero());
    vehicles.push_back(car("stray", -1073741824.0, -1073741824.0));
    VehicleSnapshot sparse;
    sparse.assign(vehicles, kernel::SimTime::zero());
    std::uniform_real_distribution<double> coordinate(-450, 450);
    std::size_t found = 0;
    for (const VehicleSnapshot* s : {&compact, &sparse}) {
        NeighbourGrid grid;
        grid.build(*s, 40);
        for (int k = 0; k < 50; ++k) {
            const double x = coordinate(rng);
            const double y = coordinate(rng);
            for (const double radius : {0.0, 30.0, 100.0, 5000.0}) {
                std::vector<Index> expected;
                for (Index j = 0; j < s->size(); ++j) {
                    const double dx = s->positions()(0, j) - x;
                    const double dy = s->positions()(1, j) - y;
                    if (dx * dx + dy * dy <= radius * radius) expected.push_back(j);
                }
                ASSERT_EQ(grid.around(x, y, radius), expected) << "(" << x << ", " << y << "), radius " << radius;
                found += expected.size();
            }
        }
    }
    EXPECT_GT(found, 1000u);  // not vacuous
    // Inclusive, and a vehicle standing on the point counts.
    VehicleSnapshot s;
    s.assign({car("a", 0, 0), car("b", 3, 4)}, kernel::SimTime::zero());
    NeighbourGrid grid;
    grid.build(s, 5);
    EXPECT_EQ(grid.around(0, 0, 5), (std::vector<Index>{0, 1}));
    EXPECT_EQ(grid.around(0, 0, 4.999), (std::vector<Index>{0}));
}

TEST(NeighbourGrid, RebuildsForANewSnapshot) {
    VehicleSnapshot s;
    s.assign({car("a", 0, 0), car("b", 3, 0)}, kernel::SimTime::zero());
    NeighbourGrid grid;
    grid.build(s, 10);
    EXPECT_EQ(grid.within(0, 5), (std::vector<Index>{1}));
    s.assign({car("a", 0, 0), car("b", 30, 0), car("c", 0, -2)}, kernel::SimTime::fromSeconds(1));
    grid.build(s, 10);
    EXPECT_EQ(grid.within(0, 5), (std::vector<Index>{2}));
    s.assign({}, kernel::SimTime::fromSeconds(2));
    grid.build(s, 10);
    s.assign({car("z", 1, 1)}, kernel::SimTime::fromSeconds(3));
    grid.build(s, 10);
    EXPECT_TRUE(grid.within(0, 100).empty());
}

TEST(NeighbourGrid, RejectsABadCellSize) {
    VehicleSnapshot s;
    NeighbourGrid grid;
    EXPECT_THROW(grid.build(s, 0), std::invalid_argument);
    EXPECT_THROW(grid.build(s, -1), std::invalid_argument);
    EXPECT_THROW(grid.build(s, std::numeric_limits<double>::infinity()), std::invalid_argument);
    EXPECT_THROW(grid.build(s, std::nan("")), std::invalid_argument);
}

// markWithin is within() as a bit set (read back ascending: the same indices), with each marked
// vehicle's squared distance as the test computes it, bit for bit, in the dense layout (random
// places, a lattice with exact distances, one spot), the hashed one (a stray far-off position) and
// for a radius of many cells.
TEST(NeighbourGrid, MarkWithinIsWithinAsABitSetWithTheSquaredDistances) {
    const auto check = [](const Eigen::Matrix2Xd& p, double cell, double radius) {
        NeighbourGrid grid;
        grid.build(p, cell);
        const auto n = static_cast<std::size_t>(p.cols());
        std::vector<std::uint64_t> marks((n + 63) / 64, 0);
        std::vector<double> squared(n, -1);
        for (Index i = 0; i < p.cols(); ++i) {
            grid.markWithin(i, radius, marks.data(), squared.data());
            std::vector<Index> got;
            for (std::size_t w = 0; w < marks.size(); ++w) {
                for (std::uint64_t bits = marks[w]; bits != 0; bits &= bits - 1)
                    got.push_back(static_cast<Index>(w * 64 + static_cast<std::size_t>(std::countr_zero(bits))));
                marks[w] = 0;
            }
            ASSERT_EQ(got, grid.within(i, radius)) << "vehicle " << i;
            for (const Index j : got) {
                const double dx = p(0, j) - p(0, i);
                const double dy = p(1, j) - p(1, i);
                ASSERT_EQ(std::bit_cast<std::uint64_t>(squared[static_cast<std::size_t>(j)]),
                          std::bit_cast<std::uint64_t>(dx * dx + dy * dy));
                ASSERT_EQ(std::sqrt(squared[static_cast<std::size_t>(j)]), (p.col(j) - p.col(i)).norm());
            }
        }
    };
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> place(0, 3000);
    Eigen::Matrix2Xd p(2, 700);
    for (Eigen::Index i = 0; i < p.cols(); ++i) p.col(i) << place(rng), place(rng);
    check(p, 125, 500);
    check(p, 10, 300);  // a radius of thirty cells
    Eigen::Matrix2Xd lattice(2, 100);
    for (Eigen::Index i = 0; i < 100; ++i) lattice.col(i) << 30.0 * (i % 10), 40.0 * (i / 10);  // 3-4-5 triangles
    lattice.col(99) = lattice.col(98);                                                          // two on one spot
    check(lattice, 25, 50);
    Eigen::Matrix2Xd stray = p;
    stray.col(3) << 1e7, -4e6;  // far off: hashed cells
    check(stray, 125, 500);
}

}  // namespace
}  // namespace sbsim::traffic
