#include "sbsim/kernel/SimTime.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace sbsim::kernel {

SimTime SimTime::fromSeconds(double seconds) {
    const double ns = std::round(seconds * static_cast<double>(kPerSecond));
    if (!std::isfinite(ns) || std::fabs(ns) >= 9.2e18) {
        throw std::out_of_range(fmt::format("simulation time out of range: {:f} s", seconds));
    }
    return SimTime(static_cast<rep>(ns));
}

void SimTime::throwOverflow() {
    throw std::out_of_range("simulation time out of range: the result is beyond about ±292 years");
}

std::string SimTime::str() const {
    // Magnitudes of both parts: min() has no positive counterpart, but its parts do.
    const rep whole = ns_ / kPerSecond;
    const rep frac = ns_ % kPerSecond;
    std::string out =
        fmt::format("{}{}.{:09}", ns_ < 0 ? "-" : "", whole < 0 ? -whole : whole, frac < 0 ? -frac : frac);
    out.erase(out.find_last_not_of('0') + 1);  // "1.050000000" → "1.05", "1.000000000" → "1."
    if (out.back() == '.') out.pop_back();
    return out;
}

}  // namespace sbsim::kernel
