#include "sbsim/radio/channel/LoadMonitor.h"

#include <algorithm>

namespace sbsim::radio {

void LoadMonitor::addStation(kernel::SimTime now) {
    busy_.push_back(0);
    busySince_.push_back(now);
    windowStart_.push_back(now);
    busyNs_.push_back(0);
    cbr_.push_back(0);
    dcc_.emplace_back();
}

void LoadMonitor::setBusy(Slot s, bool busy, kernel::SimTime now) {
    if (busy == static_cast<bool>(busy_[s])) return;
    if (!busy) busyNs_[s] += (now - busySince_[s]).raw();
    busy_[s] = busy;
    busySince_[s] = now;
}

void LoadMonitor::sample(kernel::SimTime now, const std::vector<std::uint8_t>& present, std::vector<Slot>& changed) {
    changed.clear();
    for (Slot s = 0; s < size(); ++s) {
        if (busy_[s]) {
            busyNs_[s] += (now - busySince_[s]).raw();
            busySince_[s] = now;
        }
        const kernel::SimTime window = now - windowStart_[s];
        if (present[s] && window > kernel::SimTime::zero()) {
            cbr_[s] = static_cast<double>(busyNs_[s]) / static_cast<double>(window.raw());
            const auto state = dcc_[s].state();
            const std::size_t substate = dcc_[s].activeSubstate();
            dcc_[s].update(cbr_[s]);
            if (dcc_[s].state() != state || dcc_[s].activeSubstate() != substate) changed.push_back(s);
            if (!figures_) figures_.emplace();
            ++figures_->samples;
            cbrSum_ += cbr_[s];
            figures_->meanCbr = cbrSum_ / static_cast<double>(figures_->samples);
            figures_->maxCbr = std::max(figures_->maxCbr, cbr_[s]);
        }
        busyNs_[s] = 0;
        windowStart_[s] = now;
    }
}

}  // namespace sbsim::radio
