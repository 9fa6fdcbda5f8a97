#pragma once

#include <cstdint>
#include <random>

#include "sbsim/kernel/Export.h"

namespace sbsim::kernel {

/// A seeded source of random numbers for the storyboard's random conditions. Streams with the same
/// seed and different indices are independent, so adding a random condition to a story does not
/// shift the draws of the others. Output is the same on every platform and standard library.
class SBSIM_API RandomStream {
public:
    RandomStream(std::uint64_t seed, unsigned index);

    std::uint64_t seed() const { return seed_; }
    unsigned index() const { return index_; }

    /// Uniform in [0, 1), from 53 random bits (every value a multiple of 2^-53).
    double uniform01();
    /// Uniform in [a, b) (a + (b - a) * uniform01(), as OMNeT++'s uniform()).
    double uniform(double a, double b) { return a + (b - a) * uniform01(); }

private:
    std::uint64_t seed_;
    unsigned index_;
    std::mt19937_64 engine_;
};

}  // namespace sbsim::kernel
