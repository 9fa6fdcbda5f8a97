#include "sbsim/radio/channel/ChannelSettings.h"

#include <cmath>
#include <stdexcept>

#include "sbsim/radio/channel/FrameErrorTable.h"
#include "sbsim/radio/propagation/PathLossModels.h"

namespace sbsim::radio {

kernel::SimTime ChannelSettings::airtime(std::size_t frameBytes) const {
    // Data bits per symbol: 24 at 3 Mbit/s … 216 at 27 (every allowed rate gives a whole number).
    const auto perSymbol = static_cast<std::size_t>(std::lround(rateMbps * 8));
    const std::size_t bits = 16 + 8 * frameBytes + 6;
    const auto symbols = static_cast<kernel::SimTime::rep>((bits + perSymbol - 1) / perSymbol);
    return kernel::SimTime::fromNanoseconds(40'000 + symbols * 8'000);
}

void ChannelSettings::validate() const {
    const auto require = [](bool ok, const char* what) {
        if (!ok) throw std::invalid_argument(what);
    };
    require(std::isfinite(powerDbm), "power_dbm must be a number");
    const double rates[] = {3, 4.5, 6, 9, 12, 18, 24, 27};
    bool knownRate = false;
    for (const double r : rates) knownRate = knownRate || r == rateMbps;
    require(knownRate, "rate_mbps must be one of 3, 4.5, 6, 9, 12, 18, 24, 27");
    require(frequencyHz > 0, "frequency_hz must be > 0");
    require(bandwidthHz > 0, "bandwidth_hz must be > 0");
    require(std::isfinite(noiseDbm) && std::isfinite(sensingDbm) && std::isfinite(interferenceFloorDbm),
            "noise_dbm, sensing_dbm and interference_floor_dbm must be numbers");
    require(shadowingSigmaDb >= 0, "shadowing_sigma_db must be >= 0");
    require(shadowingCorrelation >= 0 && std::isfinite(shadowingCorrelation), "shadowing_correlation_m must be >= 0");
    require(nakagamiM >= 0.5, "nakagami_m must be >= 0.5");
    require(wallDb >= 0 && perMetreDb >= 0, "obstacle losses must be >= 0 dB");
    require(aifsn >= 1 && aifsn <= 15, "aifsn must be 1 to 15");
    require(contentionWindow >= 0 && contentionWindow <= 1023, "contention_window must be 0 to 1023");
    require(queueLimit >= 1, "queue_limit must be >= 1");
    require(delay >= 0 && delayMin >= 0 && delayMax >= delayMin && delayShape > 0,
            "delays must be >= 0 s, delay_max_s >= delay_min_s, delay_shape > 0");
    require(linksPerChunk >= 1, "links_per_chunk must be >= 1");
    require(traceRange >= 0, "trace_range must be >= 0 m");
    require(tierMarginDb >= 0 && tierMarginDb <= 100, "tier_margin_db must be 0 to 100");
    require(farCellM >= 0 && farCellM <= 1000, "far_cell_m must be 0 to 1000");
    (void)FrameErrorTable(ferTable);  // throws on a malformed table
    (void)makePathLoss();
}

std::unique_ptr<PathLoss> ChannelSettings::makePathLoss() const {
    return PathLossModels::make(pathLoss, frequencyHz, pathLossKeys);
}

}  // namespace sbsim::radio
