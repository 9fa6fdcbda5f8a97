#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Message.h"

namespace sbsim::kernel {

/// The scheduled messages ordered by (arrival time, priority, insertion order), a strict total
/// order, so equal times are broken deterministically and the delivery order does not depend on
/// how the set stores them. Each message knows where it is stored, which makes cancelling cheap
/// without tombstones in the heap. Messages handed over with a unique_ptr are owned by the set
/// until delivered; self-messages stay owned by their module.
///
/// Most events of a run come a fixed delay after the event that schedules them (a timer's period,
/// the medium's latency): such events, taken in the order they are scheduled, are already in key
/// order. A delay (and priority) that recurs gets a lane, a first-in first-out ring of slots
/// appended at its tail and taken at its head: no sift, and no write into the messages that other
/// events' moves would make. A lane takes an event only if it sorts after the lane's last (a delay
/// that goes back in time, say after a clock reset, goes to the heap): each lane stays sorted, and
/// the next event is the least of the lanes' heads and the heap's top, so the order is the same
/// total order whatever lane or heap an event went to.
///
/// The heap (events of other delays: random phases, a story's timers) has four children per node,
/// and each slot keeps its message's key: a sift compares slots of one or two cache lines instead
/// of reading the messages, over half the levels of a binary heap.
class SBSIM_API FutureEventSet {
public:
    FutureEventSet() = default;
    ~FutureEventSet();
    FutureEventSet(const FutureEventSet&) = delete;
    FutureEventSet& operator=(const FutureEventSet&) = delete;

    void insert(Message& msg, SimTime at, Module* target);
    void insert(std::unique_ptr<Message> msg, SimTime at, Module* target);
    void remove(Message& msg);

    bool empty() const { return size_ == 0; }
    std::size_t size() const { return size_; }
    /// How many of them are in lanes rather than the heap (for tests: the lanes serve).
    std::size_t inLanes() const { return size_ - heap_.size(); }
    /// The next message to deliver; the set must not be empty.
    const Message& peek() const { return *nextSlot().msg; }
    /// The next message's arrival time, from the set's own copy of it (the message is not read);
    /// the set must not be empty.
    SimTime peekTime() const { return nextSlot().at; }

    /// Takes the next message out. `owned` receives it if the set owned it. The one after it is
    /// fetched into the cache meanwhile (the caller handles this one first).
    Message& pop(std::unique_ptr<Message>& owned);

    /// Drops every message addressed to `target` (the module is going away).
    void removeAllFor(const Module& target);
    /// Drops every message (the simulation is going away): one pass, where removeAllFor() per
    /// module would walk the whole set once per module.
    void clear();

private:
    static constexpr std::size_t kArity = 4;
    /// A heap slot: the message's ordering key, copied in, and the message.
    struct Entry {
        SimTime at;
        std::uint64_t order;
        int priority;
        Message* msg;
    };
    /// A lane's slot (its priority is the lane's); a null message: cancelled, skipped at the head.
    struct Slot {
        SimTime at;
        std::uint64_t order;
        Message* msg;
        Module* target;
    };
    struct Lane {
        SimTime::rep delay = 0;
        int priority = 0;
        std::vector<Slot> ring;            // a power of two long; position p at ring[p & (size - 1)]
        std::uint64_t head = 0, tail = 0;  // positions: [head, tail) held, head's live unless empty
        std::size_t live = 0;
        Slot& at(std::uint64_t position) { return ring[position & (ring.size() - 1)]; }
        const Slot& at(std::uint64_t position) const { return ring[position & (ring.size() - 1)]; }
    };
    static constexpr std::size_t kLanes = 8;
    static constexpr std::size_t kRecent = 4;
    // Message::heapIndex_ of a message in a lane: this bit, the lane in the bits above kLaneShift,
    // its position below. A heap index stays below it; kNotScheduled (all ones) is neither.
    static constexpr std::size_t kInLane = std::size_t{1} << 62;
    static constexpr unsigned kLaneShift = 58;
    static constexpr std::size_t kPositionMask = (std::size_t{1} << kLaneShift) - 1;
    /// Where the next event is: a lane's index, kHeap, kNone (empty) or kUnknown (to be found).
    static constexpr int kHeap = -1, kNone = -2, kUnknown = -3;
    static bool before(const Entry& a, const Entry& b) {
        if (a.at != b.at) return a.at < b.at;
        if (a.priority != b.priority) return a.priority < b.priority;
        return a.order < b.order;
    }
    void place(std::size_t i, const Entry& e) {
        e.msg->heapIndex_ = i;
        heap_[i] = e;
    }
    void siftUp(std::size_t i);
    void siftDown(std::size_t i);
    /// Takes heap slot `i` out; the message is no longer scheduled (the caller frees it if it was owned).
    Message& takeFromHeap(std::size_t i);
    /// Takes the slot at `position` of lane `lane` out, as takeFromHeap().
    Message& takeFromLane(std::size_t lane, std::uint64_t position);
    /// The lane an event `delay` after the last delivered one, of `priority`, arriving at `at`,
    /// goes to; none: the heap.
    Lane* laneFor(SimTime::rep delay, int priority, SimTime at);
    /// Where the next event is (next_), found if unknown.
    int next() const;
    Entry nextSlot() const;
    /// Fetches the next event's message (and a lane's target) into the cache.
    void prefetchNext() const;

    std::vector<Entry> heap_;
    std::array<Lane, kLanes> lanes_;
    std::size_t laneCount_ = 0;
    // The last delays (and priorities) that found no lane: a lane is opened for one that recurs.
    std::array<std::pair<SimTime::rep, int>, kRecent> recent_{};
    std::size_t recentNext_ = 0;
    std::size_t size_ = 0;
    SimTime clock_;  // the last delivered event's time: what an event's delay is counted from
    mutable int next_ = kNone;
    std::uint64_t nextInsertion_ = 0;
};

}  // namespace sbsim::kernel
