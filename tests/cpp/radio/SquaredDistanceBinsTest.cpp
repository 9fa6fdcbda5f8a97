// A link's distance bin and range test from its squared distance agree with the root's own
// (Medium::countLink's distance / 50, and distance <= range) everywhere: at each step's square and
// one ulp either side, at squares of exact distances on the bins' edges, and at random squares.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "sbsim/radio/disc/SquaredDistanceBins.h"

namespace sbsim::radio {
namespace {

void expectAsTheRoot(const SquaredDistanceBins& bins, double range, double squared) {
    const double distance = std::sqrt(squared);
    EXPECT_EQ(squared <= bins.maxSquared(), distance <= range) << "square " << squared << ", range " << range;
    if (squared <= bins.maxSquared())
        EXPECT_EQ(bins.of(squared), SquaredDistanceBins::binOf(distance)) << "square " << squared;
}

TEST(SquaredDistanceBins, AgreeWithTheRootAtEveryEdgeAndAtRandom) {
    std::mt19937_64 rng(11);
    for (const double range : {500.0, 499.99, 300.0, 1000.0 / 3, 150.0, 37.5, 4000.0}) {
        const SquaredDistanceBins bins(range);
        EXPECT_EQ(bins.of(bins.maxSquared()), SquaredDistanceBins::binOf(range));
        for (double edge = 0; edge <= range + 100; edge += 50) {
            const double s = edge * edge;
            for (const double q :
                 {s, std::nextafter(s, 0.0), std::nextafter(s, 1e300), std::nextafter(std::nextafter(s, 0.0), 0.0)})
                expectAsTheRoot(bins, range, q);
            // The squares whose root rounds onto the edge, and just off it.
            const double d = std::nextafter(edge, 0.0);
            expectAsTheRoot(bins, range, d * d);
            const double u = std::nextafter(edge, 1e300);
            expectAsTheRoot(bins, range, u * u);
        }
        for (const double q : {bins.maxSquared(), std::nextafter(bins.maxSquared(), 0.0),
                               std::nextafter(bins.maxSquared(), 1e300), range * range})
            expectAsTheRoot(bins, range, q);
        std::uniform_real_distribution<double> square(0, range * range);
        for (int k = 0; k < 20000; ++k) expectAsTheRoot(bins, range, square(rng));
    }
}

TEST(SquaredDistanceBins, AVeryLongRangeTakesTheRoot) {
    const SquaredDistanceBins bins(1e7);  // 200,000 bins: no table
    for (const double d : {0.0, 49.999, 50.0, 123456.7, 9999999.0})
        EXPECT_EQ(bins.of(d * d), SquaredDistanceBins::binOf(std::sqrt(d * d)));
    EXPECT_THROW(SquaredDistanceBins(-1), std::invalid_argument);
}

}  // namespace
}  // namespace sbsim::radio
