#include "sbsim/radio/disc/SquaredDistanceBins.h"

#include <algorithm>
#include <bit>
#include <limits>
#include <stdexcept>

namespace sbsim::radio {

namespace {
/// The first non-negative double in [lo, hi) past which `above` holds (above(lo) false, above(hi)
/// true, `above` never falls back): non-negative doubles order as their bits.
template <typename Above>
double firstAbove(double lo, double hi, Above above) {
    auto a = std::bit_cast<std::uint64_t>(lo);
    auto b = std::bit_cast<std::uint64_t>(hi);
    while (b - a > 1) {
        const std::uint64_t mid = a + (b - a) / 2;
        (above(std::bit_cast<double>(mid)) ? b : a) = mid;
    }
    return std::bit_cast<double>(b);
}
}  // namespace

SquaredDistanceBins::SquaredDistanceBins(double range) {
    if (!(range >= 0) || !std::isfinite(range)) throw std::invalid_argument("distance bins: range must be >= 0");
    const auto beyond = [range](double squared) { return std::sqrt(squared) > range; };
    const double past = firstAbove(0.0, range * range * 1.001 + 1, beyond);
    maxSquared_ = std::nextafter(past, 0.0);
    const std::size_t bins = binOf(range) + 1;
    steps_.assign(1, -std::numeric_limits<double>::infinity());
    for (std::size_t b = 1; b < bins; ++b) {
        const double edge = static_cast<double>(b + 1) * Medium::kDistanceBin;
        steps_.push_back(firstAbove(0.0, edge * edge, [b](double squared) { return binOf(std::sqrt(squared)) >= b; }));
    }
    steps_.push_back(std::numeric_limits<double>::infinity());
    // Cells of half the first bin's square: most hold no step, none more than one.
    const double cell = Medium::kDistanceBin * Medium::kDistanceBin / 2;
    const double cells = maxSquared_ / cell + 2;
    if (cells > 65536 || bins > 65535) return;  // then the root per link
    perCell_ = 1 / cell;
    cells_.resize(static_cast<std::size_t>(cells) + 1);
    for (std::size_t m = 0; m < cells_.size(); ++m) {
        const double lowest = static_cast<double>(m) * cell;
        cells_[m] = static_cast<std::uint16_t>(std::upper_bound(steps_.begin() + 1, steps_.end() - 1, lowest) -
                                               (steps_.begin() + 1));
    }
}

}  // namespace sbsim::radio
