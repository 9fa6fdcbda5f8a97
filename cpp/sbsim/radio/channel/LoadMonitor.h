#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/Medium.h"
#include "sbsim/radio/channel/DccStateMachine.h"

namespace sbsim::radio {

/// The channel model's load monitor: per station the channel busy ratio of each 100 ms window
/// (busy: the station senses the channel busy or sends) and the ETSI DCC state it drives; over
/// the run, the mean and largest ratio. Struct-of-arrays by the channel's station slot.
class LoadMonitor {
public:
    using Slot = std::int32_t;

    /// A new station, slot size() (slots are never reused), idle from `now`.
    void addStation(kernel::SimTime now);
    Slot size() const { return static_cast<Slot>(cbr_.size()); }
    /// The station's channel counts busy (or idle) from `now` on.
    void setBusy(Slot s, bool busy, kernel::SimTime now);
    /// Closes every station's window at `now` (every DccStateMachine::kSampling): stations present
    /// in the last snapshot get a ratio, feed their DCC and count in the figures. The stations
    /// whose DCC state changed go into `changed` (cleared first), in slot order.
    void sample(kernel::SimTime now, const std::vector<std::uint8_t>& present, std::vector<Slot>& changed);

    double busyRatio(Slot s) const { return cbr_[s]; }
    const DccStateMachine& dcc(Slot s) const { return dcc_[s]; }
    const std::optional<Medium::LoadFigures>& figures() const { return figures_; }

private:
    std::vector<std::uint8_t> busy_;
    std::vector<kernel::SimTime> busySince_, windowStart_;
    std::vector<kernel::SimTime::rep> busyNs_;
    std::vector<double> cbr_;
    std::vector<DccStateMachine> dcc_;
    std::optional<Medium::LoadFigures> figures_;
    double cbrSum_ = 0;
};

}  // namespace sbsim::radio
