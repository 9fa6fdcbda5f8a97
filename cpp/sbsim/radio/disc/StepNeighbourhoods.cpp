#include "sbsim/radio/disc/StepNeighbourhoods.h"

#include <algorithm>
#include <bit>

namespace sbsim::radio {

void StepNeighbourhoods::build(const traffic::NeighbourGrid& grid, const Eigen::Matrix2Xd& positions, double radius) {
    const auto n = static_cast<std::size_t>(positions.cols());
    const std::size_t words = (n + 63) / 64;
    marks_.assign(words, 0);
    below_.assign(n, 0);
    aboveStart_.resize(n + 1);
    aboveOthers_.clear();
    aboveDistance_.clear();
    // Each pair once, from its lower end: its neighbours above it marked in a bit set, read back
    // ascending with their distances.
    for (std::size_t i = 0; i < n; ++i) {
        aboveStart_[i] = aboveOthers_.size();
        const auto self = static_cast<Index>(i);
        grid.markWithinAbove(self, radius, marks_.data());
        const Eigen::Vector2d at = positions.col(self);
        for (std::size_t w = i / 64; w < words; ++w) {
            for (std::uint64_t bits = marks_[w]; bits != 0; bits &= bits - 1) {
                const auto j = static_cast<Index>(w * 64 + static_cast<std::size_t>(std::countr_zero(bits)));
                aboveOthers_.push_back(j);
                aboveDistance_.push_back((positions.col(j) - at).norm());
                ++below_[static_cast<std::size_t>(j)];
            }
            marks_[w] = 0;
        }
    }
    aboveStart_[n] = aboveOthers_.size();
    // Each row: its neighbours below it (written as the lower ends ascend), then those above.
    start_.resize(n + 1);
    cursor_.resize(n);
    start_[0] = 0;
    for (std::size_t i = 0; i < n; ++i) {
        cursor_[i] = start_[i];
        start_[i + 1] = start_[i] + below_[i] + (aboveStart_[i + 1] - aboveStart_[i]);
    }
    others_.resize(start_[n]);
    distance_.resize(start_[n]);
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t at = start_[i] + below_[i];
        for (std::size_t k = aboveStart_[i]; k < aboveStart_[i + 1]; ++k, ++at) {
            const auto j = static_cast<std::size_t>(aboveOthers_[k]);
            const double d = aboveDistance_[k];
            others_[at] = aboveOthers_[k];
            distance_[at] = d;
            others_[cursor_[j]] = static_cast<Index>(i);
            distance_[cursor_[j]++] = d;
        }
    }
}

}  // namespace sbsim::radio
