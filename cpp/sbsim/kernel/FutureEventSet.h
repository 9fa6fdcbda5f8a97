#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Message.h"

namespace sbsim::kernel {

/// Binary heap of scheduled messages ordered by (arrival time, priority, insertion order), so equal
/// times are broken deterministically. Each message knows its heap slot, which makes cancelling
/// O(log n) without tombstones. Messages handed over with a unique_ptr are owned by the set until
/// delivered; self-messages stay owned by their module.
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

private:
    struct Entry {
        Message* msg;
        std::unique_ptr<Message> owned;
    };
    static bool before(const Message& a, const Message& b);
    void place(std::size_t i, Entry e);
    void siftUp(std::size_t i);
    void siftDown(std::size_t i);
    Entry take(std::size_t i);

    std::vector<Entry> heap_;
    std::uint64_t nextInsertion_ = 0;
};

}  // namespace sbsim::kernel
