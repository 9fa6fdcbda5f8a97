#include "sbsim/kernel/RandomStream.h"

namespace sbsim::kernel {

namespace {
std::mt19937_64 seededEngine(std::uint64_t seed, unsigned index) {
    // seed_seq keeps only 32 bits of each value, so the 64-bit seed goes in as two halves.
    std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                           static_cast<std::uint32_t>(index)};
    return std::mt19937_64(sequence);
}
}  // namespace

RandomStream::RandomStream(std::uint64_t seed, unsigned index)
    : seed_(seed), index_(index), engine_(seededEngine(seed, index)) {}

double RandomStream::uniform01() {
    // std::uniform_real_distribution's algorithm is implementation-defined; this is not.
    return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

}  // namespace sbsim::kernel
