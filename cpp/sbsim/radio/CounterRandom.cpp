#include "sbsim/radio/CounterRandom.h"

#include <array>
#include <cmath>
#include <numbers>

namespace sbsim::radio {

namespace {
/// Marsaglia and Tsang's ziggurat for the standard normal ("The Ziggurat Method for Generating
/// Random Variables", J. Stat. Softw. 5(8), 2000), built here from its definition: kLayers boxes of
/// equal area v under f(x) = exp(−x²/2), x ≥ 0. Box i spans [0, x[i]] × [f(x[i]), f(x[i+1])];
/// box 0 is the base strip [0, r] × [0, f(r)] plus the tail beyond r, given the width v / f(r).
/// A point uniform in a box lies under the curve for sure when its x < x[i+1] (about 99 % of
/// draws: one 64-bit word, a multiply and a compare); otherwise the wedge or the tail decides.
/// The draw is exact (no approximation of the distribution), unlike a table of the inverse CDF.
struct Ziggurat {
    static constexpr int kLayers = 256;
    std::array<double, kLayers + 1> x{};
    std::array<double, kLayers + 1> f{};
    double r = 0;

    Ziggurat() {
        // r such that the kLayers boxes exactly fill the area under f: bisection on the top box's
        // surplus (larger r, thinner tail, smaller boxes, more of them needed).
        double lo = 3;
        double hi = 4;
        for (int k = 0; k < 100; ++k) {
            const double mid = 0.5 * (lo + hi);
            (fill(mid) > 0 ? lo : hi) = mid;
        }
        fill(hi);
    }

    static double density(double t) { return std::exp(-0.5 * t * t); }

    /// Builds the boxes from r; returns > 0 when they reach the top before the last layer (r too
    /// small), < 0 when the last box is too small to close the top.
    double fill(double tail) {
        r = tail;
        const double v = r * density(r) + std::sqrt(std::numbers::pi / 2) * std::erfc(r / std::numbers::sqrt2);
        x[0] = v / density(r);
        x[1] = r;
        for (int i = 1; i < kLayers; ++i) {
            const double top = density(x[i]) + v / x[i];
            if (top >= 1) return 1;
            x[i + 1] = std::sqrt(-2 * std::log(top));
        }
        // The last box [0, x[kLayers−1]] × [f(x[kLayers−1]), 1] must have area v: x[kLayers] = 0.
        const double surplus = x[kLayers - 1] * (1 - density(x[kLayers - 1])) - v;
        x[kLayers] = 0;
        for (int i = 0; i <= kLayers; ++i) f[i] = density(x[i]);
        f[0] = 0;  // the base strip starts at the axis
        return -surplus;
    }
};

const Ziggurat& ziggurat() {
    static const Ziggurat table;
    return table;
}
}  // namespace

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
    const Ziggurat& z = ziggurat();
    for (;;) {
        // One word: the layer from bits 0–7, the sign from bit 8, the position from bits 11–63.
        const std::uint64_t bits = next();
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
