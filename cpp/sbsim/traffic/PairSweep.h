#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "sbsim/kernel/ParallelFor.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::traffic {

/// Every pair of vehicles of one snapshot whose positions are within `radius` of each other
/// (dx·dx + dy·dy <= radius·radius, NeighbourGrid::forEachWithin's test, symmetric), each pair
/// visited once. The vehicles are sorted into square cells a little wider than the radius, row by
/// row; each cell is swept against itself, the next cell of its row and the three cells of the row
/// above (half of the 3x3 stencil), so a pair costs one distance test where a search per vehicle
/// (forEachWithin for each) costs two. Rows of cells are independent, for a pool. Kept apart from
/// NeighbourGrid (which stays one search per vehicle) so that the grid's many includers do not change.
class PairSweep {
public:
    using Index = VehicleSnapshot::Index;

    /// Sorts `snapshot`'s vehicles (positions copied) into cells for `radius`.
    /// Throws std::invalid_argument unless radius is finite and >= 0.
    void build(const VehicleSnapshot& snapshot, double radius);

    /// Rows of occupied cells: each pair belongs to exactly one.
    std::size_t rows() const { return rowStart_.empty() ? 0 : rowStart_.size() - 1; }

    /// Calls `visit(a, b)` (a != b, either may be the smaller index) once for every pair of row
    /// `row` within the radius. The order of the calls is unspecified.
    template <typename Visit>
    void forEachPairInRow(std::size_t row, Visit&& visit) const;

    /// forEachPairInRow over all rows.
    template <typename Visit>
    void forEachPair(Visit&& visit) const {
        for (std::size_t row = 0; row < rows(); ++row) forEachPairInRow(row, visit);
    }

    using Pair = std::pair<Index, Index>;
    /// Calls `emit(a, b, out)` for every pair within the radius, a row of cells per task on `pool`;
    /// `emit` appends to `out` what the caller keeps of the pair (none, (a, b), (b, a), ...). The
    /// kept pairs, sorted, go into `kept`: the same whatever the thread count. `rowScratch` holds
    /// the rows' buffers from step to step.
    template <typename Emit>
    void collectSorted(kernel::ParallelFor& pool, std::vector<std::vector<Pair>>& rowScratch, std::vector<Pair>& kept,
                       Emit&& emit) const;

private:
    struct Cell {
        std::int32_t cx, cy;
        std::int32_t begin;  // its vehicles are items [begin, next cell's begin)
    };

    double r2_ = 0;
    // The vehicles in cell order (row by row, then column), ascending index within a cell.
    std::vector<double> xs_, ys_;
    std::vector<Index> indices_;
    std::vector<Cell> cells_;              // occupied cells in order, then one whose begin is the end
    std::vector<std::uint32_t> rowStart_;  // row k is cells_[rowStart_[k], rowStart_[k + 1])
    // Scratch, kept to avoid reallocating each step.
    std::vector<std::pair<std::int32_t, std::int32_t>> cellOfVehicle_;  // (column, row)
    std::vector<std::uint32_t> bucketOfVehicle_;
    std::vector<std::int32_t> counts_;
};

template <typename Visit>
void PairSweep::forEachPairInRow(std::size_t row, Visit&& visit) const {
    const double r2 = r2_;
    const double* const xs = xs_.data();
    const double* const ys = ys_.data();
    const auto test = [&](std::int32_t a, std::int32_t b) {
        const double dx = xs[b] - xs[a];
        const double dy = ys[b] - ys[a];
        if (dx * dx + dy * dy <= r2)
            visit(indices_[static_cast<std::size_t>(a)], indices_[static_cast<std::size_t>(b)]);
    };
    const std::uint32_t first = rowStart_[row];
    const std::uint32_t last = rowStart_[row + 1];
    // The row above, if it is the next row of cells: its cells from column cx - 1 to cx + 1 are
    // one run, found by two cursors that only move right as cx grows.
    const bool above = row + 1 < rows() && std::int64_t{cells_[last].cy} == std::int64_t{cells_[first].cy} + 1;
    const std::uint32_t aboveEnd = above ? rowStart_[row + 2] : last;
    std::uint32_t from = last;
    std::uint32_t to = last;
    for (std::uint32_t c = first; c < last; ++c) {
        const Cell& cell = cells_[c];
        const std::int32_t begin = cell.begin;
        const std::int32_t end = cells_[c + 1].begin;
        // Itself and the next cell of the row, as one run.
        const std::int32_t runEnd =
            c + 1 < last && std::int64_t{cells_[c + 1].cx} == std::int64_t{cell.cx} + 1 ? cells_[c + 2].begin : end;
        std::int32_t upBegin = 0;
        std::int32_t upEnd = 0;
        if (above) {
            while (from < aboveEnd && std::int64_t{cells_[from].cx} < std::int64_t{cell.cx} - 1) ++from;
            if (to < from) to = from;
            while (to < aboveEnd && std::int64_t{cells_[to].cx} <= std::int64_t{cell.cx} + 1) ++to;
            upBegin = cells_[from].begin;
            upEnd = cells_[to].begin;
        }
        for (std::int32_t a = begin; a < end; ++a) {
            for (std::int32_t b = a + 1; b < runEnd; ++b) test(a, b);
            for (std::int32_t b = upBegin; b < upEnd; ++b) test(a, b);
        }
    }
}

template <typename Emit>
void PairSweep::collectSorted(kernel::ParallelFor& pool, std::vector<std::vector<Pair>>& rowScratch,
                              std::vector<Pair>& kept, Emit&& emit) const {
    const std::size_t n = rows();
    if (rowScratch.size() < n) rowScratch.resize(n);
    pool.run(
        n,
        [&](std::size_t begin, std::size_t end) {
            for (std::size_t row = begin; row < end; ++row) {
                std::vector<Pair>& out = rowScratch[row];
                out.clear();
                forEachPairInRow(row, [&](Index a, Index b) { emit(a, b, out); });
            }
        },
        1);
    kept.clear();
    for (std::size_t row = 0; row < n; ++row) kept.insert(kept.end(), rowScratch[row].begin(), rowScratch[row].end());
    std::sort(kept.begin(), kept.end());
}

}  // namespace sbsim::traffic
