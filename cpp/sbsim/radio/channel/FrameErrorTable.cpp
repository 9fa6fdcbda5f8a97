#include "sbsim/radio/channel/FrameErrorTable.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sbsim/radio/Decibels.h"

namespace sbsim::radio {

FrameErrorTable::FrameErrorTable(std::vector<std::pair<double, double>> points) : given_(std::move(points)) {
    if (given_.empty()) throw std::invalid_argument("a FER table needs at least one point");
    for (std::size_t k = 0; k < given_.size(); ++k) {
        const auto [ebN0, fer] = given_[k];
        if (!std::isfinite(ebN0) || !(fer > 0 && fer <= 1))
            throw std::invalid_argument("a FER table's points are (Eb/N0 dB, FER in (0, 1])");
        if (k > 0 && !(ebN0 > given_[k - 1].first))
            throw std::invalid_argument("a FER table's Eb/N0 values must ascend strictly");
        points_.emplace_back(ebN0, std::log10(fer));
    }
}

FrameErrorTable FrameErrorTable::goubet6Mbps() {
    return FrameErrorTable({{0, 1}, {5, 1}, {10, 0.4}, {15, 1.5e-2}, {20, 4e-3}, {25, 3e-3}, {30, 2e-3}, {35, 1e-3}});
}

double FrameErrorTable::ferAtEbN0Db(double ebN0Db) const {
    // 10^y as dbToLinear(10 y): this runs twice per decoded link, and libm's pow is slower.
    if (!(ebN0Db > points_.front().first)) return dbToLinear(10 * points_.front().second);
    if (ebN0Db >= points_.back().first) return dbToLinear(10 * points_.back().second);
    const auto upper = std::upper_bound(points_.begin(), points_.end(), ebN0Db,
                                        [](double v, const std::pair<double, double>& p) { return v < p.first; });
    const auto& [x1, y1] = *upper;
    const auto& [x0, y0] = *(upper - 1);
    return dbToLinear(10 * (y0 + (y1 - y0) * (ebN0Db - x0) / (x1 - x0)));
}

double FrameErrorTable::fer(double sinrDb, double bandwidthHz, double rateBps) const {
    return ferAtEbN0Db(sinrDb + 10 * std::log10(bandwidthHz / rateBps));
}

}  // namespace sbsim::radio
