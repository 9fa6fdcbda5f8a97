#include "sbsim/radio/channel/FarCells.h"

#include <algorithm>
#include <cmath>

namespace sbsim::radio {

namespace {
/// Beyond this many cells in the stations' bounding box (a stray far-off position) the step
/// computes every link per receiver instead.
constexpr std::int64_t kMaxDenseCells = 1 << 24;
/// A position this far out is no place (SUMO's invalid position is −2^30 m): such a station has
/// no cell, its links are its own.
constexpr double kNoPlace = 1e7;

bool placed(double x, double y) { return std::abs(x) < kNoPlace && std::abs(y) < kNoPlace; }
}  // namespace

FarCells::Cell FarCells::idOf(std::int32_t cx, std::int32_t cy) {
    const std::uint64_t key =
        (static_cast<std::uint64_t>(static_cast<std::uint32_t>(cx)) << 32) | static_cast<std::uint32_t>(cy);
    const auto [it, added] = ids_.try_emplace(key, static_cast<Cell>(centreX_.size()));
    if (added) {
        centreX_.push_back((cx + 0.5) * size_);
        centreY_.push_back((cy + 0.5) * size_);
    }
    return it->second;
}

void FarCells::fillBeyond(double x, double y, double radius, double range, BeyondTable& table) const {
    table.x = x;
    table.y = y;
    table.range = range;
    table.x0 = coordinate(x - radius);
    table.y0 = coordinate(y - radius);
    // A cell id of kNoCell is never in the table: coordinate() stays within ±1e9.
    table.width = coordinate(x + radius) - table.x0 + 1;
    table.height = coordinate(y + radius) - table.y0 + 1;
    table.beyond.resize(static_cast<std::size_t>(table.width) * static_cast<std::size_t>(table.height));
    std::size_t k = 0;
    for (std::int32_t row = 0; row < table.height; ++row) {
        for (std::int32_t column = 0; column < table.width; ++column) {
            table.beyond[k++] = cellBeyond(table.x0 + column, table.y0 + row, x, y, range) ? 1 : 0;
        }
    }
}

void FarCells::newStep(const ChannelStations& stations) {
    const std::size_t n = stations.present.size();
    cellOf_.assign(n, -1);
    cx_.resize(n);
    cy_.resize(n);
    std::int32_t x0 = 0, x1 = -1, y0 = 0, y1 = -1;
    bool any = false;
    for (std::size_t s = 0; s < n; ++s) {
        if (!stations.present[s] || !placed(stations.x[s], stations.y[s])) continue;
        cx_[s] = coordinate(stations.x[s]);
        cy_[s] = coordinate(stations.y[s]);
        if (!any) {
            x0 = x1 = cx_[s];
            y0 = y1 = cy_[s];
            any = true;
        }
        x0 = std::min(x0, cx_[s]);
        x1 = std::max(x1, cx_[s]);
        y0 = std::min(y0, cy_[s]);
        y1 = std::max(y1, cy_[s]);
    }
    const std::int64_t area =
        any ? (static_cast<std::int64_t>(x1) - x0 + 1) * (static_cast<std::int64_t>(y1) - y0 + 1) : 0;
    usable_ = any && area <= kMaxDenseCells;
    byIndex_.assign(stations.slotOfIndex.size(), IndexCell{kNoCell, kNoCell});
    if (!usable_) {
        std::fill(cellOf_.begin(), cellOf_.end(), -1);
        memberStart_.clear();
        members_.clear();
        return;
    }
    lowX_ = x0;
    lowY_ = y0;
    width_ = x1 - x0 + 1;
    height_ = y1 - y0 + 1;
    dense_.assign(static_cast<std::size_t>(area), -1);
    occupants_.assign(static_cast<std::size_t>(area), 0);
    for (std::size_t s = 0; s < n; ++s) {
        if (!stations.present[s] || !placed(stations.x[s], stations.y[s])) continue;
        const std::size_t k = static_cast<std::size_t>(cy_[s] - lowY_) * static_cast<std::size_t>(width_) +
                              static_cast<std::size_t>(cx_[s] - lowX_);
        if (dense_[k] < 0) dense_[k] = idOf(cx_[s], cy_[s]);
        cellOf_[s] = dense_[k];
        ++occupants_[k];
    }
    for (std::size_t j = 0; j < byIndex_.size(); ++j) {
        const Slot s = stations.slotOfIndex[j];
        if (s >= 0 && static_cast<std::size_t>(s) < n && cellOf_[s] >= 0) byIndex_[j] = {cx_[s], cy_[s]};
    }
    // Members by cell id (counting sort, slots ascending within a cell).
    memberStart_.assign(cells() + 1, 0);
    for (std::size_t s = 0; s < n; ++s) {
        if (cellOf_[s] >= 0) ++memberStart_[static_cast<std::size_t>(cellOf_[s]) + 1];
    }
    for (std::size_t c = 0; c < cells(); ++c) memberStart_[c + 1] += memberStart_[c];
    members_.resize(memberStart_.back());
    std::vector<std::uint32_t>& next = scratch_;
    next.assign(memberStart_.begin(), memberStart_.end() - 1);
    for (std::size_t s = 0; s < n; ++s) {
        if (cellOf_[s] >= 0) members_[next[static_cast<std::size_t>(cellOf_[s])]++] = static_cast<Slot>(s);
    }
}

}  // namespace sbsim::radio
