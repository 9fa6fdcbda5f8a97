#include "sbsim/radio/CounterRandom.h"

#include <cmath>
#include <numbers>

namespace sbsim::radio {

CounterRandom::CounterRandom(std::uint64_t seed, std::uint64_t sender, std::uint64_t sequence, std::uint64_t receiver,
                             DrawPurpose purpose)
    : CounterRandom(Keyed{}, frameKey(seed, sender, sequence), receiver, purpose) {}

CounterRandom::CounterRandom(Keyed, std::uint64_t frameKey, std::uint64_t receiver, DrawPurpose purpose) {
    const std::uint64_t k = mix(frameKey ^ (receiver + 0x8CB92BA72F3D8DD7ULL));
    key_ = mix(k ^ (static_cast<std::uint64_t>(purpose) + 0xF1357AEA2E62A9C5ULL));
}

std::uint64_t CounterRandom::frameKey(std::uint64_t seed, std::uint64_t sender, std::uint64_t sequence) {
    // Each component goes through the mixer with a distinct odd offset, so swapping two of them
    // (sender and receiver of the reverse link) gives an unrelated key.
    std::uint64_t k = mix(seed + 0x9E3779B97F4A7C15ULL);
    k = mix(k ^ (sender + 0xD1B54A32D192ED03ULL));
    return mix(k ^ (sequence + 0xAEF17502108EF2D9ULL));
}

CounterRandom CounterRandom::ofFrame(std::uint64_t frameKey, std::uint64_t receiver, DrawPurpose purpose) {
    return {Keyed{}, frameKey, receiver, purpose};
}

std::uint64_t CounterRandom::keyOf(std::string_view stationId) {
    std::uint64_t h = 0xCBF29CE484222325ULL;
    for (const char c : stationId) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001B3ULL;
    }
    return mix(h);
}

std::uint64_t CounterRandom::next() {
    // Two rounds: the first decorrelates consecutive counters of one key, the second the keys.
    return mix(mix(key_ + (counter_++) * 0x9E3779B97F4A7C15ULL) ^ key_);
}

double CounterRandom::normal() {
    const double u1 = 1.0 - uniform01();  // (0, 1]: the logarithm stays finite
    const double u2 = uniform01();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

double CounterRandom::gamma(double shape) {
    if (shape < 1.0) {
        // Boost to shape + 1 and scale back (Marsaglia and Tsang's note).
        const double u = 1.0 - uniform01();
        return gamma(shape + 1.0) * std::pow(u, 1.0 / shape);
    }
    const double d = shape - 1.0 / 3.0;
    const double c = 1.0 / std::sqrt(9.0 * d);
    for (;;) {
        double x = 0;
        double v = 0;
        do {
            x = normal();
            v = 1.0 + c * x;
        } while (v <= 0);
        v = v * v * v;
        const double u = 1.0 - uniform01();
        if (u < 1.0 - 0.0331 * x * x * x * x) return d * v;
        if (std::log(u) < 0.5 * x * x + d * (1.0 - v + std::log(v))) return d * v;
    }
}

}  // namespace sbsim::radio
