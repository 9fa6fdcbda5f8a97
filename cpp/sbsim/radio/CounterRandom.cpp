#include "sbsim/radio/CounterRandom.h"

#include <cmath>
#include <numbers>

namespace sbsim::radio {

CounterRandom::CounterRandom(std::uint64_t seed, std::uint64_t sender, std::uint64_t sequence, std::uint64_t receiver,
                             DrawPurpose purpose)
    : CounterRandom(Keyed{}, frameKey(seed, sender, sequence), receiver, purpose) {}

std::uint64_t CounterRandom::frameKey(std::uint64_t seed, std::uint64_t sender, std::uint64_t sequence) {
    // Each component goes through the mixer with a distinct odd offset, so swapping two of them
    // (sender and receiver of the reverse link) gives an unrelated key.
    std::uint64_t k = mix(seed + 0x9E3779B97F4A7C15ULL);
    k = mix(k ^ (sender + 0xD1B54A32D192ED03ULL));
    return mix(k ^ (sequence + 0xAEF17502108EF2D9ULL));
}

std::uint64_t CounterRandom::keyOf(std::string_view stationId) {
    std::uint64_t h = 0xCBF29CE484222325ULL;
    for (const char c : stationId) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001B3ULL;
    }
    return mix(h);
}

double CounterRandom::normalBeyondBoxes(std::uint64_t bits) {
    const Ziggurat& z = Ziggurat::instance();
    for (;;) {
        const auto layer = static_cast<int>(bits & 0xFF);
        const double sign = (bits & 0x100) != 0 ? -1.0 : 1.0;
        const double t = static_cast<double>(bits >> 11) * 0x1.0p-53 * z.x[layer];
        if (t < z.x[layer + 1]) return sign * t;
        if (layer == 0) {
            // The tail beyond r (Marsaglia's method): exponential proposals, accepted under the curve.
            for (;;) {
                const double a = -std::log(1.0 - uniform01()) / z.r;
                const double b = -std::log(1.0 - uniform01());
                if (2 * b > a * a) return sign * (z.r + a);
            }
        }
        // The wedge between the box and the curve.
        const double y = z.f[layer] + uniform01() * (z.f[layer + 1] - z.f[layer]);
        if (y < Ziggurat::density(t)) return sign * t;
        bits = next();
    }
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
