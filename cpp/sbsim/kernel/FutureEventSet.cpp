#include "sbsim/kernel/FutureEventSet.h"

#include <stdexcept>
#include <utility>

namespace sbsim::kernel {

Message::~Message() {
    if (fes_ != nullptr && isScheduled()) fes_->remove(*this);
}

void Message::setPriority(int priority) {
    if (isScheduled()) throw std::logic_error("cannot change the priority of scheduled message '" + name_ + "'");
    priority_ = priority;
}

FutureEventSet::~FutureEventSet() { clear(); }

void FutureEventSet::clear() {
    // Taken out of the heap first: an owned message's destructor then finds itself unscheduled.
    std::vector<Entry> all;
    all.swap(heap_);
    for (const Entry& e : all) {
        e.msg->heapIndex_ = Message::kNotScheduled;
        e.msg->fes_ = nullptr;
    }
    for (const Entry& e : all) {
        if (e.msg->ownedBySet_) delete e.msg;
    }
}

void FutureEventSet::insert(Message& msg, SimTime at, Module* target) {
    if (msg.isScheduled()) throw std::logic_error("message '" + msg.name() + "' is already scheduled");
    msg.arrival_ = at;
    msg.target_ = target;
    msg.insertionOrder_ = nextInsertion_++;
    msg.fes_ = this;
    msg.ownedBySet_ = false;
    heap_.push_back(Entry{at, msg.insertionOrder_, msg.priority_, &msg});
    msg.heapIndex_ = heap_.size() - 1;
    siftUp(heap_.size() - 1);
}

void FutureEventSet::insert(std::unique_ptr<Message> msg, SimTime at, Module* target) {
    Message& m = *msg;
    insert(m, at, target);
    m.ownedBySet_ = true;
    msg.release();  // the set frees it (remove, clear) or hands it back (pop)
}

void FutureEventSet::remove(Message& msg) {
    if (msg.fes_ != this || !msg.isScheduled()) return;
    Message& m = take(msg.heapIndex_);
    // An owned message being cancelled dies here, as it would have after delivery.
    if (m.ownedBySet_) delete &m;
}

Message& FutureEventSet::pop(std::unique_ptr<Message>& owned) {
    if (heap_.empty()) throw std::logic_error("pop from an empty future-event set");
    Message& m = take(0);
    if (m.ownedBySet_) owned.reset(&m);
    return m;
}

void FutureEventSet::removeAllFor(const Module& target) {
    // Collect first: removing re-orders the heap under an index loop.
    std::vector<Message*> doomed;
    for (const Entry& e : heap_) {
        if (e.msg->target_ == &target) doomed.push_back(e.msg);
    }
    for (Message* m : doomed) remove(*m);
}

Message& FutureEventSet::take(std::size_t i) {
    Message& out = *heap_[i].msg;
    out.heapIndex_ = Message::kNotScheduled;
    out.fes_ = nullptr;
    const Entry last = heap_.back();
    heap_.pop_back();
    if (i < heap_.size()) {
        place(i, last);
        if (i > 0 && before(heap_[i], heap_[(i - 1) / kArity])) {
            siftUp(i);
        } else {
            siftDown(i);
        }
    }
    return out;
}

void FutureEventSet::siftUp(std::size_t i) {
    const Entry moving = heap_[i];
    while (i > 0) {
        const std::size_t parent = (i - 1) / kArity;
        if (!before(moving, heap_[parent])) break;
        place(i, heap_[parent]);
        i = parent;
    }
    place(i, moving);
}

void FutureEventSet::siftDown(std::size_t i) {
    const std::size_t n = heap_.size();
    const Entry moving = heap_[i];
    while (true) {
        const std::size_t first = kArity * i + 1;
        if (first >= n) break;
        // The least of up to four children (the key order is total: no ties to break).
        std::size_t best = first;
        const std::size_t end = first + kArity < n ? first + kArity : n;
        for (std::size_t c = first + 1; c < end; ++c) {
            if (before(heap_[c], heap_[best])) best = c;
        }
        if (!before(heap_[best], moving)) break;
        place(i, heap_[best]);
        i = best;
    }
    place(i, moving);
}

}  // namespace sbsim::kernel
