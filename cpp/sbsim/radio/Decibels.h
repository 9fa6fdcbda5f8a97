#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace sbsim::radio {

namespace detail {
/// e^x by its series in long double: exact to double precision for |x| ≤ ln 2, and constexpr.
constexpr double expSeries(double x) {
    long double term = 1;
    long double sum = 1;
    for (int k = 1; k < 30; ++k) {
        term *= static_cast<long double>(x) / k;
        sum += term;
    }
    return static_cast<double>(sum);
}
/// 2^(j/64), j = 0…63.
inline constexpr std::array<double, 64> kSixtyFourthPowersOfTwo = [] {
    std::array<double, 64> t{};
    for (int j = 0; j < 64; ++j) t[j] = expSeries(j / 64.0 * std::numbers::ln2);
    return t;
}();
}  // namespace detail

/// 10^(dB/10): a power in dBm to mW (or any dB ratio to linear). Runs once per link and frame,
/// so it avoids libm: 10^(x/10) = 2^y, y = k/64 + t with |t| ≤ 1/128; 2^(k/64) from a table,
/// 2^t by a degree-5 polynomial (truncation below 4e-17), the power of two written into the
/// exponent. Within 4e-15 relative of std::pow (as std::exp of the same argument is).
inline double dbToLinear(double db) {
    if (!(std::abs(db) < 3000)) return std::pow(10.0, db / 10);  // huge, infinite or NaN: rare, exact
    const double y = db * (std::numbers::log2e * std::numbers::ln10 / 10);
    constexpr double kRound = 0x1.8p52;  // adding and subtracting it rounds to an integer (to nearest)
    const double k = (y * 64 + kRound) - kRound;
    const double w = (y - k / 64) * std::numbers::ln2;
    const double p = 1 + w * (1 + w * (1.0 / 2 + w * (1.0 / 6 + w * (1.0 / 24 + w * (1.0 / 120)))));
    const auto n = static_cast<std::int64_t>(k);
    const double scale = std::bit_cast<double>(static_cast<std::uint64_t>((n >> 6) + 1023) << 52);
    return detail::kSixtyFourthPowersOfTwo[static_cast<std::size_t>(n & 63)] * p * scale;
}

/// 10 log10(linear): mW to dBm, a linear ratio to dB.
inline double linearToDb(double linear) { return 10.0 * std::log10(linear); }

}  // namespace sbsim::radio
