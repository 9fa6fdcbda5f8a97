#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "sbsim/kernel/Message.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/V2xMessage.h"
#include "sbsim/radio/channel/ChannelSettings.h"

namespace sbsim::radio {

/// 802.11p broadcast channel access (EDCA, one access category, no ACKs), per station: the frames
/// waiting, then AIFS and a backoff of 0..CW slots counted down only while the station senses the
/// channel idle. Struct-of-arrays by the channel's station slot. It owns the stations' access
/// timers; its module schedules them (Clock) and, when one fires, puts the station's head frame
/// on the air (take()).
class ChannelAccess {
public:
    using Slot = std::int32_t;
    static constexpr int kTimerKind = 1;
    /// A station's access timer (kind kTimerKind): its backoff has ended.
    struct Timer : kernel::Message {
        explicit Timer(Slot s) : kernel::Message("channel access", kTimerKind), station(s) {}
        Slot station;
    };
    /// The module's clock and event scheduling, which the timers go through.
    class Clock {
    public:
        virtual kernel::SimTime now() const = 0;
        virtual void schedule(kernel::SimTime at, kernel::Message& timer) = 0;
        virtual void cancel(kernel::Message& timer) = 0;

    protected:
        ~Clock() = default;
    };

    /// `settings` and `clock` must outlive this.
    ChannelAccess(const ChannelSettings& settings, Clock& clock) : settings_(settings), clock_(clock) {}
    /// The run's seed, for the backoff draws (before the first frame).
    void setSeed(std::uint64_t seed) { seed_ = seed; }
    /// A new station, slot size(); `key` is CounterRandom::keyOf(its id).
    void addStation(std::uint64_t key);
    Slot size() const { return static_cast<Slot>(keys_.size()); }

    /// Queues `frame`; false (dropped) when the station's queue is full.
    bool enqueue(Slot s, std::shared_ptr<const V2xMessage> frame);
    std::size_t queued(Slot s) const { return queue_[s].size(); }
    bool contending(Slot s) const { return contending_[s] != 0; }
    /// Contends for the head frame: draws its backoff, and counts down at once unless the channel is busy.
    void start(Slot s, bool channelBusy);
    /// The station senses the channel busy from now: the backoff freezes (the slots that passed
    /// idle are spent). A backoff ending now sends anyway: frames starting in one slot collide.
    void channelBusy(Slot s);
    /// The station senses the channel idle from now: AIFS, then the rest of the backoff.
    void channelIdle(Slot s);
    /// The station's timer fired: its head frame leaves the queue for the air.
    std::shared_ptr<const V2xMessage> take(Slot s);
    /// The station's own frame ended: AIFS again (from now if the channel is idle), and the next
    /// frame contends.
    void frameEnded(Slot s, bool channelBusy);

private:
    void scheduleCountdown(Slot s);

    const ChannelSettings& settings_;
    Clock& clock_;
    std::uint64_t seed_ = 0;
    std::vector<std::uint64_t> keys_;
    std::vector<std::deque<std::shared_ptr<const V2xMessage>>> queue_;
    std::vector<std::uint8_t> contending_;
    std::vector<std::int32_t> backoff_;  // slots left
    std::vector<kernel::SimTime> countStart_, idleSince_;
    std::vector<std::unique_ptr<Timer>> timers_;
};

}  // namespace sbsim::radio
