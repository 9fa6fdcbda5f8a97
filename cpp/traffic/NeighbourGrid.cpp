#include "traffic/NeighbourGrid.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace sbsim::traffic {

void NeighbourGrid::build(const VehicleSnapshot& snapshot, double cellSize) {
    if (!(cellSize > 0) || !std::isfinite(cellSize)) {
        throw std::invalid_argument("neighbour grid: cell size must be finite and > 0, not " +
                                    std::to_string(cellSize));
    }
    snapshot_ = &snapshot;
    cellSize_ = cellSize;
    inverseCellSize_ = 1 / cellSize;

    const Index n = snapshot.size();
    const Eigen::Matrix2Xd& positions = snapshot.positions();
    // At least twice as many buckets as vehicles keeps collisions rare.
    const std::size_t buckets = std::bit_ceil(std::max<std::size_t>(2, 2 * static_cast<std::size_t>(n)));
    shift_ = 64 - static_cast<unsigned>(std::countr_zero(buckets));

    // Counting sort by bucket: count, prefix sum, place (stable, so a bucket is in index order).
    bucketStart_.assign(buckets + 1, 0);
    bucketScratch_.resize(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) {
        const std::size_t b = bucketOf(cellCoordinate(positions(0, i), inverseCellSize_),
                                       cellCoordinate(positions(1, i), inverseCellSize_));
        bucketScratch_[i] = static_cast<std::uint32_t>(b);
        ++bucketStart_[b + 1];
    }
    for (std::size_t b = 0; b < buckets; ++b) bucketStart_[b + 1] += bucketStart_[b];
    items_.resize(static_cast<std::size_t>(n));
    // bucketStart_[b] serves as the insertion cursor of bucket b, then is restored by one shift.
    for (Index i = 0; i < n; ++i) {
        const double x = positions(0, i);
        const double y = positions(1, i);
        const std::int32_t cx = cellCoordinate(x, inverseCellSize_);
        const std::int32_t cy = cellCoordinate(y, inverseCellSize_);
        items_[bucketStart_[bucketScratch_[i]]++] = Item{x, y, cellKey(cx, cy), i};
    }
    for (std::size_t b = buckets; b > 0; --b) bucketStart_[b] = bucketStart_[b - 1];
    bucketStart_[0] = 0;
}

std::vector<NeighbourGrid::Index> NeighbourGrid::within(Index i, double radius) const {
    std::vector<Index> out;
    forEachWithin(i, radius, [&out](Index j) { out.push_back(j); });
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace sbsim::traffic
