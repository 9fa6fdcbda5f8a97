#include "sbsim/radio/Ziggurat.h"

#include <cmath>
#include <numbers>

namespace sbsim::radio {

const Ziggurat& Ziggurat::instance() {
    static const Ziggurat table;
    return table;
}

double Ziggurat::density(double t) { return std::exp(-0.5 * t * t); }

Ziggurat::Ziggurat() {
    // Larger r: a thinner tail, smaller boxes, more of them needed to reach the top.
    double lo = 3;
    double hi = 4;
    for (int k = 0; k < 100; ++k) {
        const double mid = 0.5 * (lo + hi);
        (fill(mid) > 0 ? lo : hi) = mid;
    }
    fill(hi);
}

double Ziggurat::fill(double tail) {
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
    f[0] = 0;
    return -surplus;
}

}  // namespace sbsim::radio
