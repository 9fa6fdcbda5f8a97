// Neighbourhoods kept across steps (Verlet lists) answer as a fresh search would: against brute
// force over random walks with vehicles coming and going, a vehicle jumping past the skin, and keys
// whose order is not the positions' order; and they are kept (few epochs) while vehicles move little.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

#include "sbsim/radio/disc/KeptNeighbourhoods.h"

namespace sbsim::radio {
namespace {

using Index = KeptNeighbourhoods::Index;
using Key = KeptNeighbourhoods::Key;
using Indices = KeptNeighbourhoods::Indices;

/// NeighbourGrid's answer by brute force: j != i with dx² + dy² <= r², ascending.
Indices bruteForce(const Eigen::Matrix2Xd& p, Index i, double r) {
    Indices out;
    for (Index j = 0; j < p.cols(); ++j) {
        const double dx = p(0, j) - p(0, i);
        const double dy = p(1, j) - p(1, i);
        if (j != i && dx * dx + dy * dy <= r * r) out.push_back(j);
    }
    return out;
}

/// Vehicle i's neighbours from `kept`; each one's square checked: the test's own, whose root is
/// the bits of the positions' difference's norm() (as the disc model's distances were taken).
Indices within(KeptNeighbourhoods& kept, const Eigen::Matrix2Xd& p, Index i) {
    Indices got{-7};  // appended after what `out` holds
    KeptNeighbourhoods::Squares squared{-1.0};
    kept.within(i, got, squared);
    EXPECT_EQ(got.size(), squared.size());
    EXPECT_EQ(got.front(), -7);
    EXPECT_EQ(squared.front(), -1.0);
    for (std::size_t k = 1; k < got.size() && k < squared.size(); ++k) {
        const Index j = got[k];
        const double dx = p(0, j) - p(0, i);
        const double dy = p(1, j) - p(1, i);
        EXPECT_EQ(std::bit_cast<std::uint64_t>(squared[k]), std::bit_cast<std::uint64_t>(dx * dx + dy * dy));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(std::sqrt(squared[k])),
                  std::bit_cast<std::uint64_t>((p.col(j) - p.col(i)).norm()))
            << "vehicles " << i << " and " << j;
    }
    return Indices(got.begin() + 1, got.end());
}

void expectAllMatch(KeptNeighbourhoods& kept, const Eigen::Matrix2Xd& p, int step) {
    for (Index i = 0; i < p.cols(); ++i) {
        ASSERT_EQ(within(kept, p, i), bruteForce(p, i, kept.radius())) << "step " << step << ", vehicle " << i;
    }
}

/// Vehicles by key, each step in ascending key order (as a snapshot's ids), some leaving and coming.
struct Fleet {
    std::vector<Key> keys;
    std::vector<double> xs, ys;
    Eigen::Matrix2Xd positions() const {
        Eigen::Matrix2Xd p(2, static_cast<Eigen::Index>(keys.size()));
        for (std::size_t k = 0; k < keys.size(); ++k) p.col(static_cast<Eigen::Index>(k)) << xs[k], ys[k];
        return p;
    }
};

TEST(KeptNeighbourhoods, MatchRandomWalksWithArrivalsAndDepartures) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> place(0, 2000), step(-3, 3), coin(0, 1);
    Fleet fleet;
    Key nextKey = 0;
    for (int k = 0; k < 300; ++k) {
        fleet.keys.push_back(nextKey++);
        fleet.xs.push_back(place(rng));
        fleet.ys.push_back(place(rng));
    }
    KeptNeighbourhoods kept(150, 15);
    for (int s = 0; s < 60; ++s) {
        bool changed = s == 0;
        for (std::size_t k = 0; k < fleet.keys.size(); ++k) {
            fleet.xs[k] += step(rng);
            fleet.ys[k] += step(rng);
        }
        if (s % 3 == 1) {
            // One leaves, one comes with a new key (appended: keys stay ascending) near the others.
            fleet.keys.erase(fleet.keys.begin() + s);
            fleet.xs.erase(fleet.xs.begin() + s);
            fleet.ys.erase(fleet.ys.begin() + s);
            fleet.keys.push_back(nextKey++);
            fleet.xs.push_back(fleet.xs[5] + 20);
            fleet.ys.push_back(fleet.ys[5]);
            changed = true;
        }
        const Eigen::Matrix2Xd p = fleet.positions();
        kept.update(p, fleet.keys, changed);
        expectAllMatch(kept, p, s);
    }
    // Moves of at most 4.3 m a step against a skin of 15 m: lists last a few steps at least.
    EXPECT_LT(kept.epochs(), 30u);
    EXPECT_GE(kept.epochs(), 2u);
}

TEST(KeptNeighbourhoods, AVehicleThatMovesPastTheSkinIsFound) {
    // a and b start 400 m apart (no list holds the other); b jumps next to a in one step.
    Fleet fleet{{0, 1, 2}, {0, 400, 1000}, {0, 0, 0}};
    KeptNeighbourhoods kept(100, 10);
    Eigen::Matrix2Xd p = fleet.positions();
    kept.update(p, fleet.keys, true);
    expectAllMatch(kept, p, 0);
    fleet.xs[1] = 50;
    p = fleet.positions();
    kept.update(p, fleet.keys, false);
    EXPECT_EQ(within(kept, p, 0), (Indices{1}));
    expectAllMatch(kept, p, 1);
    EXPECT_EQ(kept.epochs(), 1u) << "one jump: a new reference for it, not new lists for all";
    // It jumps back (its old place and its first new one both stale): found there, not twice.
    fleet.xs[1] = 400;
    fleet.xs[2] = 420;
    p = fleet.positions();
    kept.update(p, fleet.keys, false);
    EXPECT_EQ(within(kept, p, 2), (Indices{1}));
    expectAllMatch(kept, p, 2);

    // Two vehicles that each move a little less than half the skin towards each other: kept lists
    // (no new epoch) and still found.
    Fleet pair{{0, 1}, {0, 100 + 2 * 9.9}, {0, 0}};
    KeptNeighbourhoods both(100, 20);
    p = pair.positions();
    both.update(p, pair.keys, true);
    expectAllMatch(both, p, 0);
    pair.xs[0] += 9.9;
    pair.xs[1] -= 9.9;
    p = pair.positions();
    both.update(p, pair.keys, false);
    expectAllMatch(both, p, 1);
    EXPECT_EQ(both.epochs(), 1u);
    EXPECT_EQ(within(both, p, 1), (Indices{0}));
}

TEST(KeptNeighbourhoods, ANewcomerFindsAndIsFoundWithinTheEpoch) {
    Fleet fleet{{0, 5}, {0, 1000}, {0, 0}};
    KeptNeighbourhoods kept(100, 10);
    Eigen::Matrix2Xd p = fleet.positions();
    kept.update(p, fleet.keys, true);
    expectAllMatch(kept, p, 0);
    // Key 3 comes between the two (its index 1), next to vehicle 0.
    fleet = Fleet{{0, 3, 5}, {0, 60, 1000}, {0, 0, 0}};
    p = fleet.positions();
    kept.update(p, fleet.keys, true);
    expectAllMatch(kept, p, 1);
    EXPECT_EQ(within(kept, p, 0), (Indices{1}));
    // It moves on by 4 m (within the skin), vehicle 5 leaves: no new epoch, answers still exact.
    fleet = Fleet{{0, 3}, {0, 64}, {0, 0}};
    p = fleet.positions();
    kept.update(p, fleet.keys, true);
    expectAllMatch(kept, p, 2);
    EXPECT_EQ(kept.epochs(), 1u);
}

TEST(KeptNeighbourhoods, KeysOutOfThePositionsOrderStillAnswerAscending) {
    // The same vehicles in another order at each step (keys shuffled with them).
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> place(0, 500);
    Fleet fleet;
    for (Key k = 0; k < 80; ++k) {
        fleet.keys.push_back(k);
        fleet.xs.push_back(place(rng));
        fleet.ys.push_back(place(rng));
    }
    KeptNeighbourhoods kept(120, 10);
    for (int s = 0; s < 5; ++s) {
        std::vector<std::size_t> order(fleet.keys.size());
        std::iota(order.begin(), order.end(), 0);
        std::shuffle(order.begin(), order.end(), rng);
        Fleet shuffled;
        for (const std::size_t o : order) {
            shuffled.keys.push_back(fleet.keys[o]);
            shuffled.xs.push_back(fleet.xs[o] + s);
            shuffled.ys.push_back(fleet.ys[o]);
        }
        const Eigen::Matrix2Xd p = shuffled.positions();
        kept.update(p, shuffled.keys, true);
        expectAllMatch(kept, p, s);
    }
}

TEST(KeptNeighbourhoods, ListsThatRestartAtEveryStepDoNotLast) {
    // 100 vehicles that all move 50 m (past half the 20 m skin) each update: the newcomers
    // overflow, epochs last a step or two, and the lists say they do not pay; answers stay exact.
    Fleet fleet;
    for (Key k = 0; k < 100; ++k) {
        fleet.keys.push_back(k);
        fleet.xs.push_back(25.0 * k);
        fleet.ys.push_back(0);
    }
    KeptNeighbourhoods kept(100, 20);
    EXPECT_TRUE(kept.lasting(4)) << "until an epoch finished";
    for (int s = 0; s < 6; ++s) {
        for (double& x : fleet.xs) x += 50;
        const Eigen::Matrix2Xd p = fleet.positions();
        kept.update(p, fleet.keys, s == 0);
        expectAllMatch(kept, p, s);
    }
    EXPECT_FALSE(kept.lasting(4));
    // Then still: epochs last again.
    for (int s = 0; s < 12; ++s) {
        const Eigen::Matrix2Xd p = fleet.positions();
        kept.update(p, fleet.keys, false);
        expectAllMatch(kept, p, 100 + s);
    }
    EXPECT_FALSE(kept.lasting(4)) << "the still epoch has not finished yet";
    fleet.xs[0] += 500;
    for (double& x : fleet.xs) x += 500;
    const Eigen::Matrix2Xd p = fleet.positions();
    kept.update(p, fleet.keys, false);
    kept.update(p, fleet.keys, false);
    expectAllMatch(kept, p, 200);
    EXPECT_TRUE(kept.lasting(4));
}

TEST(KeptNeighbourhoods, RejectsABadSkin) {
    EXPECT_THROW(KeptNeighbourhoods(100, 0), std::invalid_argument);
    EXPECT_THROW(KeptNeighbourhoods(100, std::numeric_limits<double>::infinity()), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::radio
