#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Message.h"

namespace sbsim::kernel {

/// Heap of scheduled messages ordered by (arrival time, priority, insertion order), a strict total
/// order, so equal times are broken deterministically and the delivery order does not depend on the
/// heap's shape. Each message knows its heap slot, which makes cancelling O(log n) without
/// tombstones. Messages handed over with a unique_ptr are owned by the set until delivered;
/// self-messages stay owned by their module.
///
/// Four children per node, and each slot keeps its message's key: a sift compares slots of one or
/// two cache lines instead of reading the messages (a cache miss each), over half the levels of a
/// binary heap. Only the message that moves is written (its new slot).
class SBSIM_API FutureEventSet {
public:
    FutureEventSet() = default;
    ~FutureEventSet();
    FutureEventSet(const FutureEventSet&) = delete;
    FutureEventSet& operator=(const FutureEventSet&) = delete;

    void insert(Message& msg, SimTime at, Module* target);
    void insert(std::unique_ptr<Message> msg, SimTime at, Module* target);
    void remove(Message& msg);

    bool empty() const { return heap_.empty(); }
    std::size_t size() const { return heap_.size(); }
    /// The next message to deliver; the set must not be empty.
    const Message& peek() const { return *heap_.front().msg; }

    /// Takes the next message out. `owned` receives it if the set owned it.
    Message& pop(std::unique_ptr<Message>& owned);

    /// Drops every message addressed to `target` (the module is going away).
    void removeAllFor(const Module& target);
    /// Drops every message (the simulation is going away): one pass, where removeAllFor() per
    /// module would walk the whole set once per module.
    void clear();

private:
    static constexpr std::size_t kArity = 4;
    /// A slot: the message's ordering key, copied in, and the message.
    struct Entry {
        SimTime at;
        std::uint64_t order;
        int priority;
        Message* msg;
    };
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
    /// Takes slot `i` out; the message is no longer scheduled (the caller frees it if it was owned).
    Message& take(std::size_t i);

    std::vector<Entry> heap_;
    std::uint64_t nextInsertion_ = 0;
};

}  // namespace sbsim::kernel
