#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/radio/Medium.h"

namespace sbsim::radio {

/// A link's distance bin (Medium::countLink's: distance / Medium::kDistanceBin, whole) and its
/// range test from its squared distance, without the root per link: the squares at which the bin
/// steps up (and the last in range) are found once for a range, by bisection over the doubles on
/// the root's own answer, so they agree with it everywhere (sqrt and the division never fall as
/// the square grows); a table of equal cells of squares gives a bin to start from.
class SBSIM_API SquaredDistanceBins {
public:
    /// For links out to `range` m (>= 0, finite; else std::invalid_argument).
    explicit SquaredDistanceBins(double range);

    /// The bin of a link `distance` m long, as Medium::countLink takes it.
    static std::size_t binOf(double distance) { return static_cast<std::size_t>(distance / Medium::kDistanceBin); }
    /// The largest square whose root is <= the range: a link is in range iff its square is <= it.
    double maxSquared() const { return maxSquared_; }
    /// The tables by value, for a loop over many links (held in registers: no reload after each
    /// store the compiler cannot tell apart from them). Valid while the SquaredDistanceBins lives.
    struct Lookup {
        const std::uint16_t* cells;  // null: a range of very many bins, the root per link
        const double* steps;
        double perCell;
        /// binOf(std::sqrt(squared)), for 0 <= squared <= maxSquared().
        std::size_t of(double squared) const {
            if (cells == nullptr) return binOf(std::sqrt(squared));
            std::size_t b = cells[static_cast<std::int64_t>(squared * perCell)];
            while (squared < steps[b]) --b;
            while (squared >= steps[b + 1]) ++b;
            return b;
        }
    };
    Lookup lookup() const { return {cells_.empty() ? nullptr : cells_.data(), steps_.data(), perCell_}; }
    std::size_t of(double squared) const { return lookup().of(squared); }

private:
    double maxSquared_ = 0;
    double perCell_ = 0;
    /// steps_[b]: the least square in bin b (b >= 1); steps_[0] = -inf, and +inf after the last.
    std::vector<double> steps_;
    std::vector<std::uint16_t> cells_;  // the bin of each cell's lowest square
};

}  // namespace sbsim::radio
