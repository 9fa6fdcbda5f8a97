#include "sbsim/traffic/NeighbourGrid.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace sbsim::traffic {

void NeighbourGrid::build(const Eigen::Matrix2Xd& positions, double cellSize) {
    if (!(cellSize > 0) || !std::isfinite(cellSize)) {
        throw std::invalid_argument(
            fmt::format("neighbour grid: cell size must be finite and > 0, not {:f}", cellSize));
    }
    positions_ = &positions;
    cellSize_ = cellSize;
    inverseCellSize_ = 1 / cellSize;

    const auto n = static_cast<Index>(positions.cols());
    const auto cellOf = [&](Index i) {
        return std::pair{cellCoordinate(positions(0, i), inverseCellSize_),
                         cellCoordinate(positions(1, i), inverseCellSize_)};
    };

    // Dense when the bounding box of the occupied cells has at most a few cells per vehicle.
    std::int64_t minX = std::numeric_limits<std::int32_t>::max(), maxX = std::numeric_limits<std::int32_t>::min();
    std::int64_t minY = minX, maxY = maxX;
    for (Index i = 0; i < n; ++i) {
        const auto [cx, cy] = cellOf(i);
        minX = std::min<std::int64_t>(minX, cx);
        maxX = std::max<std::int64_t>(maxX, cx);
        minY = std::min<std::int64_t>(minY, cy);
        maxY = std::max<std::int64_t>(maxY, cy);
    }
    const double boxCells = n == 0 ? 0.0 : static_cast<double>(maxX - minX + 1) * static_cast<double>(maxY - minY + 1);
    dense_ = n > 0 && boxCells <= 4.0 * static_cast<double>(n) + 4096;
    std::size_t buckets = 0;
    if (dense_) {
        minX_ = static_cast<std::int32_t>(minX);
        maxX_ = static_cast<std::int32_t>(maxX);
        minY_ = static_cast<std::int32_t>(minY);
        maxY_ = static_cast<std::int32_t>(maxY);
        columns_ = static_cast<std::size_t>(maxX - minX + 1);
        buckets = static_cast<std::size_t>(boxCells);
    } else {
        // At least twice as many buckets as vehicles keeps collisions rare.
        buckets = std::bit_ceil(std::max<std::size_t>(2, 2 * static_cast<std::size_t>(n)));
        shift_ = 64 - static_cast<unsigned>(std::countr_zero(buckets));
    }

    // Counting sort by bucket: count, prefix sum, place (stable, so a bucket is in index order).
    bucketStart_.assign(buckets + 1, 0);
    bucketScratch_.resize(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) {
        const auto [cx, cy] = cellOf(i);
        const std::size_t b = bucketOf(cx, cy);
        bucketScratch_[i] = static_cast<std::uint32_t>(b);
        ++bucketStart_[b + 1];
    }
    for (std::size_t b = 0; b < buckets; ++b) bucketStart_[b + 1] += bucketStart_[b];
    items_.resize(static_cast<std::size_t>(n));
    // bucketStart_[b] serves as the insertion cursor of bucket b, then is restored by one shift.
    for (Index i = 0; i < n; ++i) {
        const auto [cx, cy] = cellOf(i);
        items_[bucketStart_[bucketScratch_[i]]++] = Item{positions(0, i), positions(1, i), cellKey(cx, cy), i};
    }
    for (std::size_t b = buckets; b > 0; --b) bucketStart_[b] = bucketStart_[b - 1];
    bucketStart_[0] = 0;
}

namespace {
/// `out` (distinct indices below `n`) in ascending order. Many of a few thousand vehicles (a V2X
/// neighbourhood: a sort was a tenth of the disc model's run at 0.1 s steps) are marked in a bit
/// set and read back in order; a few are sorted.
void ascending(std::vector<NeighbourGrid::Index>& out, std::size_t n) {
    constexpr std::size_t kBits = 64;
    const std::size_t words = (n + kBits - 1) / kBits;
    if (out.size() < kBits || words > out.size()) {
        std::sort(out.begin(), out.end());
        return;
    }
    std::vector<std::uint64_t> marked(words, 0);
    for (const NeighbourGrid::Index j : out) {
        const auto u = static_cast<std::size_t>(j);
        marked[u / kBits] |= std::uint64_t{1} << (u % kBits);
    }
    std::size_t k = 0;
    for (std::size_t w = 0; w < words; ++w) {
        for (std::uint64_t bits = marked[w]; bits != 0; bits &= bits - 1)
            out[k++] = static_cast<NeighbourGrid::Index>(w * kBits + static_cast<std::size_t>(std::countr_zero(bits)));
    }
}
}  // namespace

std::vector<NeighbourGrid::Index> NeighbourGrid::within(Index i, double radius) const {
    std::vector<Index> out;
    forEachWithin(i, radius, [&out](Index j) { out.push_back(j); });
    ascending(out, items_.size());
    return out;
}

void NeighbourGrid::markWithin(Index i, double radius, std::uint64_t* marks, double* squared) const {
    if (positions_ == nullptr || !(radius >= 0)) return;
    const Eigen::Matrix2Xd& positions = *positions_;
    const double x = positions(0, i);
    const double y = positions(1, i);
    const CellRange cells = cellsAround(x, y, radius);
    if (!dense_ || cells.beyond(static_cast<std::int64_t>(items_.size()))) {
        forEachWithin(i, radius, [&](Index j) {
            const double dx = positions(0, j) - x;
            const double dy = positions(1, j) - y;
            const auto u = static_cast<std::size_t>(j);
            squared[u] = dx * dx + dy * dy;
            marks[u / 64] |= std::uint64_t{1} << (u % 64);
        });
        return;
    }
    // visitNear's dense walk: each item of the rows' runs writes its squared distance and ORs in
    // a bit that is set only when it is not i and within the radius (a branch per candidate
    // mispredicts about a third of the time in a V2X neighbourhood).
    const double r2 = radius * radius;
    forEachDenseItem(cells, [&](const Item& it) {
        const double dx = it.x - x;
        const double dy = it.y - y;
        const double d2 = dx * dx + dy * dy;
        const auto u = static_cast<std::size_t>(it.index);
        squared[u] = d2;
        const bool in = (it.index != i) & (d2 <= r2);
        marks[u / 64] |= std::uint64_t{in} << (u % 64);
    });
}

std::vector<NeighbourGrid::Index> NeighbourGrid::around(double x, double y, double radius) const {
    std::vector<Index> out;
    forEachAround(x, y, radius, [&out](Index j) { out.push_back(j); });
    ascending(out, items_.size());
    return out;
}

}  // namespace sbsim::traffic
