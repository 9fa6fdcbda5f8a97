#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::traffic {

/// A uniform grid over the vehicle positions of one snapshot, rebuilt once per step in O(n), so
/// "who is within r metres of vehicle i" costs a few cells instead of all pairs. Used by the
/// speed-difference and TTC conditions and by the V2X medium.
class NeighbourGrid {
public:
    using Index = VehicleSnapshot::Index;

    NeighbourGrid() = default;

    /// Indexes `snapshot` (kept by reference until the next build) with square cells of `cellSize` m.
    /// Throws std::invalid_argument unless cellSize is finite and > 0.
    void build(const VehicleSnapshot& snapshot, double cellSize) { build(snapshot.positions(), cellSize); }
    /// The same over bare positions (column i: point i's x, y), kept by reference until the next
    /// build: a grid of positions that are no snapshot's (a medium's neighbourhoods kept across steps).
    void build(const Eigen::Matrix2Xd& positions, double cellSize);
    double cellSize() const { return cellSize_; }

    /// Calls `visit(j)` for every vehicle j != i whose position is within `radius` of vehicle i's
    /// (distance <= radius). Any radius works; radius <= cellSize() touches at most 3x3 cells.
    /// The order of the calls is unspecified.
    template <typename Visit>
    void forEachWithin(Index i, double radius, Visit&& visit) const;

    /// The indices of forEachWithin, in ascending order.
    std::vector<Index> within(Index i, double radius) const;

    /// forEachWithin(i, radius) as a bit set, without a branch per candidate: sets bit j of
    /// `marks` (bit j % 64 of word j / 64, one bit per vehicle) for every vehicle it visits, and
    /// writes `squared[j]` = (xj - xi)² + (yj - yi)² (the test's own value) for at least those.
    /// Read back in ascending order (and the bits cleared) by the caller.
    void markWithin(Index i, double radius, std::uint64_t* marks, double* squared) const;

    /// Calls `visit(j)` for every vehicle j whose position is within `radius` of the point (x, y):
    /// the neighbours of a place rather than of a vehicle (a roadside unit's). Order unspecified.
    template <typename Visit>
    void forEachAround(double x, double y, double radius, Visit&& visit) const {
        if (positions_ != nullptr) visitNear(x, y, radius, kNoVehicle, visit);
    }
    /// The indices of forEachAround, in ascending order.
    std::vector<Index> around(double x, double y, double radius) const;

private:
    static constexpr Index kNoVehicle = std::numeric_limits<Index>::max();
    /// forEachWithin's and forEachAround's search: every vehicle but `skip` within `radius` of (x, y).
    template <typename Visit>
    void visitNear(double x, double y, double radius, Index skip, Visit& visit) const;

    /// The cells a query of `radius` around (x, y) reads. The range is widened by a hair so that
    /// rounding in x - r cannot drop a point that the distance test accepts.
    struct CellRange {
        std::int32_t x0, x1, y0, y1;
        /// Visiting them would cost more than all `n` vehicles (a radius far beyond the cell size).
        bool beyond(std::int64_t n) const {
            const std::int64_t columns = std::int64_t{x1} - x0 + 1;
            const std::int64_t rows = std::int64_t{y1} - y0 + 1;
            return columns > n || rows > n || columns * rows > n;
        }
    };
    CellRange cellsAround(double x, double y, double radius) const {
        const double reach = radius * (1 + 1e-12) + 1e-9;
        return {cellCoordinate(x - reach, inverseCellSize_), cellCoordinate(x + reach, inverseCellSize_),
                cellCoordinate(y - reach, inverseCellSize_), cellCoordinate(y + reach, inverseCellSize_)};
    }
    /// Dense layout: every item of the cells, row by row (each row of the range is one run of items).
    template <typename Each>
    void forEachDenseItem(const CellRange& cells, Each&& each) const {
        const std::int32_t x0 = std::max(cells.x0, minX_);
        const std::int32_t x1 = std::min(cells.x1, maxX_);
        if (x0 > x1) return;
        for (std::int32_t cy = std::max(cells.y0, minY_), last = std::min(cells.y1, maxY_); cy <= last; ++cy) {
            const Item* const end = items_.data() + bucketStart_[bucketOf(x1, cy) + 1];
            for (const Item* it = items_.data() + bucketStart_[bucketOf(x0, cy)]; it != end; ++it) each(*it);
        }
    }

    // Vehicles are counting-sorted by bucket, so a bucket is one contiguous run of items_. Where the
    // vehicles' bounding box has few cells (O(n)), a bucket is one cell, numbered row by row, so the
    // cells of a query row are one run as well ("dense"). Otherwise (a network spanning tens of
    // kilometres, or a stray far-off position) cells are hashed into 2n buckets, which keeps memory
    // O(n) whatever the spread; a bucket may then hold other cells too, hence Item::cell.
    struct Item {
        double x, y;
        std::uint64_t cell;
        Index index;
    };

    static std::int32_t cellCoordinate(double v, double inverseCellSize) {
        const double c = std::floor(v * inverseCellSize);
        // Clamping (NaN to the lowest cell) keeps the mapping monotone and the cast defined.
        if (!(c >= std::numeric_limits<std::int32_t>::min())) return std::numeric_limits<std::int32_t>::min();
        if (c > std::numeric_limits<std::int32_t>::max()) return std::numeric_limits<std::int32_t>::max();
        return static_cast<std::int32_t>(c);
    }
    static std::uint64_t cellKey(std::int32_t cx, std::int32_t cy) {
        return (std::uint64_t{static_cast<std::uint32_t>(cx)} << 32) | static_cast<std::uint32_t>(cy);
    }
    std::size_t bucketOf(std::int32_t cx, std::int32_t cy) const {
        if (dense_) {
            return static_cast<std::size_t>(std::int64_t{cy} - minY_) * columns_ +
                   static_cast<std::size_t>(std::int64_t{cx} - minX_);
        }
        const std::uint64_t h = std::uint64_t{static_cast<std::uint32_t>(cx)} * 0x9E3779B97F4A7C15ULL ^
                                std::uint64_t{static_cast<std::uint32_t>(cy)} * 0xC2B2AE3D27D4EB4FULL;
        return static_cast<std::size_t>(h >> shift_);
    }

    const Eigen::Matrix2Xd* positions_ = nullptr;
    double cellSize_ = 0;
    double inverseCellSize_ = 0;
    unsigned shift_ = 63;                       // hashed: 64 - log2(bucket count)
    bool dense_ = false;                        // one bucket per cell of the bounding box
    std::int32_t minX_ = 0, minY_ = 0;          // dense: the box's first cell
    std::int32_t maxX_ = 0, maxY_ = 0;          // dense: the box's last cell
    std::size_t columns_ = 0;                   // dense: cells per row
    std::vector<std::int32_t> bucketStart_;     // bucket b is items_[bucketStart_[b], bucketStart_[b + 1])
    std::vector<Item> items_;                   // ascending vehicle index within a bucket
    std::vector<std::uint32_t> bucketScratch_;  // per vehicle, kept to avoid reallocating each step
};

template <typename Visit>
void NeighbourGrid::forEachWithin(Index i, double radius, Visit&& visit) const {
    if (positions_ == nullptr) return;
    const Eigen::Matrix2Xd& positions = *positions_;
    visitNear(positions(0, i), positions(1, i), radius, i, visit);
}

template <typename Visit>
void NeighbourGrid::visitNear(double x, double y, double radius, Index i, Visit& visit) const {
    if (!(radius >= 0)) return;
    const Eigen::Matrix2Xd& positions = *positions_;
    const double r2 = radius * radius;
    const auto near = [&](double px, double py) {
        const double dx = px - x;
        const double dy = py - y;
        return dx * dx + dy * dy <= r2;
    };
    const auto n = static_cast<std::int64_t>(items_.size());
    const CellRange cells = cellsAround(x, y, radius);
    if (cells.beyond(n)) {
        for (Index j = 0; j < static_cast<Index>(n); ++j) {
            if (j != i && near(positions(0, j), positions(1, j))) visit(j);
        }
        return;
    }
    if (dense_) {
        forEachDenseItem(cells, [&](const Item& it) {
            if (it.index != i && near(it.x, it.y)) visit(it.index);
        });
        return;
    }
    for (std::int64_t cx = cells.x0; cx <= cells.x1; ++cx) {
        for (std::int64_t cy = cells.y0; cy <= cells.y1; ++cy) {
            const auto icx = static_cast<std::int32_t>(cx);
            const auto icy = static_cast<std::int32_t>(cy);
            const std::uint64_t key = cellKey(icx, icy);
            const std::size_t b = bucketOf(icx, icy);
            const Item* const end = items_.data() + bucketStart_[b + 1];
            for (const Item* it = items_.data() + bucketStart_[b]; it != end; ++it) {
                if (it->cell == key && it->index != i && near(it->x, it->y)) visit(it->index);
            }
        }
    }
}

}  // namespace sbsim::traffic
