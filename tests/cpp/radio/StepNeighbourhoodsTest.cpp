// Every vehicle's neighbours of a step from one sweep over the pairs answer as a grid query per
// vehicle would: the same vehicles, ascending, with the distances the medium computed per sender
// (bit for bit), in dense and hashed grids, with vehicles on one spot, at the radius' edge, in
// clusters, and with a radius far beyond the grid's cells.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "sbsim/radio/disc/StepNeighbourhoods.h"
#include "sbsim/traffic/NeighbourGrid.h"

namespace sbsim::radio {
namespace {

using Index = StepNeighbourhoods::Index;

/// What the medium computed per sender: the grid's ascending answer and each one's distance.
void expectAsPerSender(const Eigen::Matrix2Xd& p, double cell, double radius) {
    traffic::NeighbourGrid grid;
    grid.build(p, cell);
    StepNeighbourhoods sweep;
    sweep.build(grid, p, radius);
    ASSERT_EQ(sweep.size(), static_cast<std::size_t>(p.cols()));
    for (Index i = 0; i < p.cols(); ++i) {
        const std::vector<Index> expected = grid.within(i, radius);
        const auto others = sweep.others(i);
        ASSERT_EQ(std::vector<Index>(others.begin(), others.end()), expected) << "vehicle " << i;
        const auto distances = sweep.distances(i);
        ASSERT_EQ(distances.size(), expected.size());
        for (std::size_t k = 0; k < expected.size(); ++k) {
            const double d = (p.col(expected[k]) - p.col(i)).norm();
            ASSERT_EQ(std::bit_cast<std::uint64_t>(distances[k]), std::bit_cast<std::uint64_t>(d))
                << "vehicle " << i << ", neighbour " << expected[k];
        }
    }
}

Eigen::Matrix2Xd randomPlaces(int n, double side, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> place(0, side);
    Eigen::Matrix2Xd p(2, n);
    for (int i = 0; i < n; ++i) p.col(i) << place(rng), place(rng);
    return p;
}

TEST(StepNeighbourhoods, MatchPerSenderQueriesOnRandomPlaces) {
    expectAsPerSender(randomPlaces(700, 3000, 1), 125, 500);  // the medium's cells: a quarter of the range
    expectAsPerSender(randomPlaces(300, 800, 2), 50, 120);
    expectAsPerSender(randomPlaces(130, 500, 3), 10, 400);  // a radius of forty cells
}

TEST(StepNeighbourhoods, MatchInHashedGridsAndWithStrayVehicles) {
    Eigen::Matrix2Xd p = randomPlaces(400, 2000, 4);
    p.col(17) << 1e7, -3e6;  // far off: the grid hashes its cells
    p.col(18) << 1e7 + 100, -3e6;
    p.col(200) << std::numeric_limits<double>::quiet_NaN(), 5;  // nobody's neighbour
    expectAsPerSender(p, 125, 500);
}

TEST(StepNeighbourhoods, MatchOnOneSpotAndAtTheEdge) {
    Eigen::Matrix2Xd p(2, 12);
    for (int i = 0; i < 4; ++i) p.col(i) << 10, 10;   // on one spot: distance 0 both ways
    p.col(4) << 110, 10;                              // exactly at the radius
    p.col(5) << std::nextafter(110.0, 1000.0), 10.0;  // one ulp beyond
    p.col(6) << 10 + 60, 10 + 80;                     // 3-4-5: exactly at the radius
    p.col(7) << 10 - 60, 10 - 80;
    for (int i = 8; i < 12; ++i) p.col(i) << 0.1 * i, 3.0 * i;
    expectAsPerSender(p, 25, 100);
    expectAsPerSender(p, 1000, 100);
}

TEST(StepNeighbourhoods, MatchInClustersAndAfterARebuild) {
    std::mt19937_64 rng(5);
    std::normal_distribution<double> spread(0, 40);
    Eigen::Matrix2Xd p(2, 600);
    for (int i = 0; i < 600; ++i) p.col(i) << 300.0 * (i % 5) + spread(rng), 700.0 * (i % 3) + spread(rng);
    expectAsPerSender(p, 125, 500);
    traffic::NeighbourGrid grid;
    StepNeighbourhoods sweep;
    grid.build(p, 125);
    sweep.build(grid, p, 500);
    // The same object over fewer vehicles: nothing of the larger step remains.
    const Eigen::Matrix2Xd q = p.leftCols(50);
    grid.build(q, 125);
    sweep.build(grid, q, 500);
    ASSERT_EQ(sweep.size(), 50u);
    for (Index i = 0; i < 50; ++i) {
        const auto others = sweep.others(i);
        EXPECT_EQ(std::vector<Index>(others.begin(), others.end()), grid.within(i, 500));
    }
}

}  // namespace
}  // namespace sbsim::radio
