#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "sbsim/radio/channel/ChannelStations.h"

namespace sbsim::radio {

/// The far tier's cells (ChannelSettings::farCellM): square cells of the plane, each with an id
/// that stays the same for the run (a frame on the air across a SUMO step adds to and takes from
/// the same cell), and per step the cell of each station and how many stations each cell holds.
/// A sender's interference-only links to a whole cell beyond the far range are one figure per
/// (frame, cell) — the mean power at the cell's centre — instead of one per (frame, receiver).
class FarCells {
public:
    using Slot = ChannelStations::Slot;
    using Cell = std::int32_t;  // -1 = none

    /// Cells of `size` m (> 0).
    explicit FarCells(double size) : size_(size), inverse_(1 / size) {}
    double size() const { return size_; }
    /// Cell ids handed out so far (an id is < cells()).
    std::size_t cells() const { return centreX_.size(); }

    /// The stations' cells and the cells' occupants for the step (the present stations').
    void newStep(const ChannelStations& stations);
    /// Whether the step has cells (false when the stations spread over too many cells to index).
    bool usable() const { return usable_; }
    /// `s`'s cell this step, -1 if it was not present at the step's start.
    Cell cellOf(Slot s) const { return static_cast<std::size_t>(s) < cellOf_.size() ? cellOf_[s] : -1; }
    /// Whether every point of `s`'s cell is at least `range` m from (x, y) (false without a cell).
    bool beyond(Slot s, double x, double y, double range) const {
        const Cell c = cellOf(s);
        return c >= 0 && cellBeyond(cx_[s], cy_[s], x, y, range);
    }
    /// cellBeyond() answered once per cell of a square around a point, for a sender's whole grid
    /// visit (~15 x 15 cells against ~1,700 vehicles tested).
    struct BeyondTable {
        std::int32_t x0 = 0, y0 = 0, width = 0, height = 0;
        double x = 0, y = 0, range = 0;
        std::vector<std::uint8_t> beyond;  // row by row
    };
    /// Fills `table` for the cells meeting the square of half-side `radius` around (x, y).
    void fillBeyond(double x, double y, double radius, double range, BeyondTable& table) const;
    /// beyond() for the station of snapshot index `j` (ChannelStations::slotOfIndex; false for no
    /// station or no cell) from (table.x, table.y): the same answer, read in the order a grid visit
    /// meets vehicles — by index rather than by slot — so a far vehicle is dropped before it is a
    /// candidate.
    bool beyondIndex(std::size_t j, const BeyondTable& table) const {
        const IndexCell c = byIndex_[j];
        const auto column = static_cast<std::uint32_t>(c.cx - table.x0);  // wraps below x0
        const auto row = static_cast<std::uint32_t>(c.cy - table.y0);
        if (column < static_cast<std::uint32_t>(table.width) && row < static_cast<std::uint32_t>(table.height)) {
            return table.beyond[row * static_cast<std::uint32_t>(table.width) + column] != 0;
        }
        return c.cx != kNoCell && cellBeyond(c.cx, c.cy, table.x, table.y, table.range);  // outside the square
    }
    /// The stations in `cell` this step, in slot order.
    std::pair<const Slot*, const Slot*> members(Cell cell) const {
        if (static_cast<std::size_t>(cell) + 1 >= memberStart_.size()) return {nullptr, nullptr};
        return {members_.data() + memberStart_[cell], members_.data() + memberStart_[cell + 1]};
    }
    /// Visits (cell, occupants, centre x, centre y, cx, cy) for every occupied cell meeting the
    /// square of half-side `radius` around (x, y), row by row.
    template <typename Visit>
    void forEachOccupied(double x, double y, double radius, Visit&& visit) const;
    /// Whether every point of cell (cx, cy) is at least `range` m from (x, y).
    bool cellBeyond(std::int32_t cx, std::int32_t cy, double x, double y, double range) const {
        const double lowX = cx * size_, lowY = cy * size_;  // the cell's lower corner
        const double dx = std::max({lowX - x, 0.0, x - (lowX + size_)});
        const double dy = std::max({lowY - y, 0.0, y - (lowY + size_)});
        return dx * dx + dy * dy >= range * range;
    }

private:
    std::int32_t coordinate(double v) const {
        return static_cast<std::int32_t>(std::floor(std::clamp(v * inverse_, -1e9, 1e9)));
    }
    Cell idOf(std::int32_t cx, std::int32_t cy);
    /// A cell's coordinates by snapshot index; kNoCell: no station or no cell (coordinate() never
    /// gives it: it clamps to ±1e9).
    struct IndexCell {
        std::int32_t cx, cy;
    };
    static constexpr std::int32_t kNoCell = std::numeric_limits<std::int32_t>::min();

    double size_, inverse_;
    std::unordered_map<std::uint64_t, Cell> ids_;
    std::vector<double> centreX_, centreY_;  // by id
    // Per slot, this step.
    std::vector<Cell> cellOf_;
    std::vector<std::int32_t> cx_, cy_;
    std::vector<IndexCell> byIndex_;  // per snapshot index
    // This step's occupied bounding box of cells, row by row: id and occupants.
    bool usable_ = false;
    std::int32_t lowX_ = 0, lowY_ = 0, width_ = 0, height_ = 0;
    std::vector<Cell> dense_;
    std::vector<std::uint32_t> occupants_;
    std::vector<std::uint32_t> memberStart_;  // by id, cells() + 1
    std::vector<Slot> members_;
    std::vector<std::uint32_t> scratch_;
};

template <typename Visit>
void FarCells::forEachOccupied(double x, double y, double radius, Visit&& visit) const {
    if (!usable_) return;
    const std::int32_t x0 = std::max(coordinate(x - radius), lowX_);
    const std::int32_t x1 = std::min(coordinate(x + radius), lowX_ + width_ - 1);
    const std::int32_t y0 = std::max(coordinate(y - radius), lowY_);
    const std::int32_t y1 = std::min(coordinate(y + radius), lowY_ + height_ - 1);
    for (std::int32_t cy = y0; cy <= y1; ++cy) {
        const std::size_t row = static_cast<std::size_t>(cy - lowY_) * static_cast<std::size_t>(width_);
        for (std::int32_t cx = x0; cx <= x1; ++cx) {
            const std::size_t k = row + static_cast<std::size_t>(cx - lowX_);
            if (occupants_[k] == 0) continue;
            const Cell c = dense_[k];
            visit(c, occupants_[k], centreX_[c], centreY_[c], cx, cy);
        }
    }
}

}  // namespace sbsim::radio
