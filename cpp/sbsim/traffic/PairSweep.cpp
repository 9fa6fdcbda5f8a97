#include "sbsim/traffic/PairSweep.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace sbsim::traffic {

namespace {
/// Beyond this, rounding in x / cellSize could put two vehicles within the radius two cells apart.
/// With cells wider than the radius by 1e-3 m, the error 4·2^-53·|x| must stay below 1e-3 m.
constexpr double kLargestSweptCoordinate = 1e12;

/// The cell of coordinate v. Truncation rather than floor (cheaper; cell 0 is two cells wide, the
/// others one): any monotone map whose cells are at least one cell wide keeps pairs within the
/// radius at most one cell apart. Clamping (NaN to the lowest cell) keeps it monotone and the cast
/// defined.
std::int32_t cellCoordinate(double v, double inverseCellSize) {
    const double c = v * inverseCellSize;
    if (!(c >= std::numeric_limits<std::int32_t>::min())) return std::numeric_limits<std::int32_t>::min();
    if (c > std::numeric_limits<std::int32_t>::max()) return std::numeric_limits<std::int32_t>::max();
    return static_cast<std::int32_t>(c);
}
}  // namespace

void PairSweep::build(const VehicleSnapshot& snapshot, double radius) {
    if (!(radius >= 0) || !std::isfinite(radius)) {
        throw std::invalid_argument(fmt::format("pair sweep: radius must be finite and >= 0, not {:f}", radius));
    }
    r2_ = radius * radius;
    const auto n = static_cast<std::size_t>(snapshot.size());
    const Eigen::Matrix2Xd& positions = snapshot.positions();
    xs_.resize(n);
    ys_.resize(n);
    indices_.resize(n);
    cells_.clear();
    rowStart_.clear();
    cellOfVehicle_.resize(n);

    // A pair within the radius is at most one cell apart on each axis (see kLargestSweptCoordinate).
    const double inverseCellSize = 1 / (radius * (1 + 1e-6) + 1e-3);
    bool swept = true;
    std::int64_t minX = std::numeric_limits<std::int32_t>::max(), maxX = std::numeric_limits<std::int32_t>::min();
    std::int64_t minY = minX, maxY = maxX;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = positions(0, static_cast<Index>(i));
        const double y = positions(1, static_cast<Index>(i));
        // Infinite and NaN positions are never within the radius of anything: their cell does not matter.
        if ((std::isfinite(x) && std::abs(x) > kLargestSweptCoordinate) ||
            (std::isfinite(y) && std::abs(y) > kLargestSweptCoordinate)) {
            swept = false;
        }
        const std::int32_t cx = cellCoordinate(x, inverseCellSize);
        const std::int32_t cy = cellCoordinate(y, inverseCellSize);
        cellOfVehicle_[i] = {cx, cy};
        minX = std::min<std::int64_t>(minX, cx);
        maxX = std::max<std::int64_t>(maxX, cx);
        minY = std::min<std::int64_t>(minY, cy);
        maxY = std::max<std::int64_t>(maxY, cy);
    }
    if (n == 0) return;
    const auto place = [&](std::size_t slot, std::size_t i) {
        xs_[slot] = positions(0, static_cast<Index>(i));
        ys_[slot] = positions(1, static_cast<Index>(i));
        indices_[slot] = static_cast<Index>(i);
    };
    const auto addCell = [&](std::int32_t cx, std::int32_t cy, std::size_t begin) {
        if (cells_.empty() || cells_.back().cy != cy) rowStart_.push_back(static_cast<std::uint32_t>(cells_.size()));
        cells_.push_back(Cell{cx, cy, static_cast<std::int32_t>(begin)});
    };

    const double boxCells = static_cast<double>(maxX - minX + 1) * static_cast<double>(maxY - minY + 1);
    if (!swept) {
        // An absurd position (beyond a billion km): every vehicle in one cell, all pairs tested.
        for (std::size_t i = 0; i < n; ++i) place(i, i);
        addCell(0, 0, 0);
    } else if (boxCells <= 4.0 * static_cast<double>(n) + 4096) {
        // Few cells per vehicle: a counting sort over the bounding box's cells, row by row.
        const auto columns = static_cast<std::size_t>(maxX - minX + 1);
        const auto bucketCount = static_cast<std::size_t>(boxCells);
        counts_.assign(bucketCount + 1, 0);
        bucketOfVehicle_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const auto [cx, cy] = cellOfVehicle_[i];
            const std::size_t b = static_cast<std::size_t>(cy - minY) * columns + static_cast<std::size_t>(cx - minX);
            bucketOfVehicle_[i] = static_cast<std::uint32_t>(b);
            ++counts_[b + 1];
        }
        for (std::size_t b = 0; b < bucketCount; ++b) {
            if (counts_[b + 1] != 0) {
                addCell(static_cast<std::int32_t>(minX + static_cast<std::int64_t>(b % columns)),
                        static_cast<std::int32_t>(minY + static_cast<std::int64_t>(b / columns)),
                        static_cast<std::size_t>(counts_[b]));
            }
            counts_[b + 1] += counts_[b];
        }
        // counts_[b] is bucket b's insertion cursor (stable: ascending index within a cell).
        for (std::size_t i = 0; i < n; ++i) place(static_cast<std::size_t>(counts_[bucketOfVehicle_[i]]++), i);
    } else {
        // Spread far apart (a network tens of kilometres wide, a stray position): sorted by cell.
        std::vector<std::size_t> order(n);
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::vector<std::pair<std::int32_t, std::int32_t>> cellOfI(n);  // row first
        for (std::size_t i = 0; i < n; ++i) cellOfI[i] = {cellOfVehicle_[i].second, cellOfVehicle_[i].first};
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return cellOfI[a] != cellOfI[b] ? cellOfI[a] < cellOfI[b] : a < b;
        });
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t i = order[k];
            place(k, i);
            if (k == 0 || cellOfI[i] != cellOfI[order[k - 1]]) addCell(cellOfI[i].second, cellOfI[i].first, k);
        }
    }
    // The end: a cell no row holds, whose begin closes the last cell (and whose cy ends the last row).
    cells_.push_back(Cell{0, 0, static_cast<std::int32_t>(n)});
    rowStart_.push_back(static_cast<std::uint32_t>(cells_.size() - 1));
}

}  // namespace sbsim::traffic
