#include "sbsim/kernel/SimTime.h"

#include <cmath>
#include <stdexcept>

namespace sbsim::kernel {

SimTime SimTime::fromSeconds(double seconds) {
    const double ns = std::round(seconds * static_cast<double>(kPerSecond));
    if (!std::isfinite(ns) || std::fabs(ns) >= 9.2e18) {
        throw std::out_of_range("simulation time out of range: " + std::to_string(seconds) + " s");
    }
    return SimTime(static_cast<rep>(ns));
}

std::string SimTime::str() const {
    const rep whole = ns_ / kPerSecond;
    rep frac = ns_ % kPerSecond;
    std::string out;
    if (ns_ < 0) {
        out = "-";
        frac = -frac;
    }
    out += std::to_string(whole < 0 ? -whole : whole);
    if (frac != 0) {
        std::string digits = std::to_string(frac);
        digits.insert(0, 9 - digits.size(), '0');
        digits.erase(digits.find_last_not_of('0') + 1);
        out += "." + digits;
    }
    return out;
}

}  // namespace sbsim::kernel
