#include "sbsim/radio/channel/ChannelAccess.h"

#include <algorithm>
#include <utility>

#include "sbsim/radio/CounterRandom.h"

namespace sbsim::radio {

void ChannelAccess::addStation(std::uint64_t key) {
    const Slot s = size();
    keys_.push_back(key);
    queue_.emplace_back();
    contending_.push_back(0);
    backoff_.push_back(0);
    countStart_.push_back(clock_.now());
    idleSince_.push_back(kernel::SimTime::zero());
    timers_.push_back(std::make_unique<Timer>(s));
}

bool ChannelAccess::enqueue(Slot s, std::shared_ptr<const V2xMessage> frame) {
    if (queue_[s].size() >= settings_.queueLimit) return false;
    queue_[s].push_back(std::move(frame));
    return true;
}

void ChannelAccess::start(Slot s, bool channelBusy) {
    const V2xMessage& head = *queue_[s].front();
    CounterRandom random(seed_, keys_[s], head.sequence(), 0, DrawPurpose::Backoff);
    backoff_[s] = static_cast<std::int32_t>(random.uniform01() * (settings_.contentionWindow + 1));
    contending_[s] = 1;
    if (!channelBusy) scheduleCountdown(s);
}

void ChannelAccess::scheduleCountdown(Slot s) {
    // The backoff counts down once the channel has been idle for AIFS.
    countStart_[s] = std::max(clock_.now(), idleSince_[s] + settings_.aifs());
    clock_.schedule(countStart_[s] + settings_.slot * backoff_[s], *timers_[s]);
}

void ChannelAccess::channelBusy(Slot s) {
    const kernel::SimTime now = clock_.now();
    // Carrier sense takes part of a slot, so a backoff ending now is not stopped.
    if (contending_[s] && timers_[s]->isScheduled() && timers_[s]->arrivalTime() > now) {
        clock_.cancel(*timers_[s]);
        if (now > countStart_[s]) {
            const auto spent = static_cast<std::int32_t>((now - countStart_[s]) / settings_.slot);
            backoff_[s] = std::max(0, backoff_[s] - spent);
        }
    }
}

void ChannelAccess::channelIdle(Slot s) {
    idleSince_[s] = clock_.now();
    if (contending_[s]) scheduleCountdown(s);
}

std::shared_ptr<const V2xMessage> ChannelAccess::take(Slot s) {
    contending_[s] = 0;
    std::shared_ptr<const V2xMessage> frame = std::move(queue_[s].front());
    queue_[s].pop_front();
    return frame;
}

void ChannelAccess::frameEnded(Slot s, bool channelBusy) {
    if (!channelBusy) idleSince_[s] = clock_.now();  // AIFS again after its own frame
    if (!queue_[s].empty()) start(s, channelBusy);
}

}  // namespace sbsim::radio
