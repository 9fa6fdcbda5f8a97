#include "sbsim/traffic/Penetration.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sbsim::traffic {

namespace {

// FNV-1a over the id, then SplitMix64's finaliser over it and the seed: stable across compilers
// and platforms (std::hash is not), and well mixed, so nearby ids ("veh1", "veh2") draw apart.
std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

}  // namespace

Penetration::Penetration(double share, std::uint64_t seed) : share_(share), seed_(seed) {
    if (!(share >= 0.0 && share <= 1.0)) {
        throw std::invalid_argument("penetration must be between 0 and 1, got " + std::to_string(share));
    }
}

double Penetration::draw(std::string_view vehicleId) const {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : vehicleId) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001b3ULL;
    }
    const std::uint64_t bits = mix(h ^ mix(seed_ + 0x9e3779b97f4a7c15ULL));
    return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

bool Penetration::equipped(std::string_view vehicleId) const {
    if (everyone()) return true;
    return draw(vehicleId) < share_;
}

}  // namespace sbsim::traffic
