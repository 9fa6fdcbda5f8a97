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

FutureEventSet::~FutureEventSet() {
    for (Entry& e : heap_) {
        e.msg->heapIndex_ = Message::kNotScheduled;
        e.msg->fes_ = nullptr;
    }
}

bool FutureEventSet::before(const Message& a, const Message& b) {
    if (a.arrival_ != b.arrival_) return a.arrival_ < b.arrival_;
    if (a.priority_ != b.priority_) return a.priority_ < b.priority_;
    return a.insertionOrder_ < b.insertionOrder_;
}

void FutureEventSet::insert(Message& msg, SimTime at, Module* target) {
    if (msg.isScheduled()) throw std::logic_error("message '" + msg.name() + "' is already scheduled");
    msg.arrival_ = at;
    msg.target_ = target;
    msg.insertionOrder_ = nextInsertion_++;
    msg.fes_ = this;
    heap_.push_back(Entry{&msg, nullptr});
    msg.heapIndex_ = heap_.size() - 1;
    siftUp(heap_.size() - 1);
}

void FutureEventSet::insert(std::unique_ptr<Message> msg, SimTime at, Module* target) {
    Message& m = *msg;
    insert(m, at, target);
    heap_[m.heapIndex_].owned = std::move(msg);
}

void FutureEventSet::remove(Message& msg) {
    if (msg.fes_ != this || !msg.isScheduled()) return;
    Entry e = take(msg.heapIndex_);
    // An owned message being cancelled dies here, as it would have after delivery.
    e.owned.reset();
}

Message& FutureEventSet::pop(std::unique_ptr<Message>& owned) {
    if (heap_.empty()) throw std::logic_error("pop from an empty future-event set");
    Entry e = take(0);
    owned = std::move(e.owned);
    return *e.msg;
}

void FutureEventSet::removeAllFor(const Module& target) {
    // Collect first: removing re-orders the heap under an index loop.
    std::vector<Message*> doomed;
    for (const Entry& e : heap_) {
        if (e.msg->target_ == &target) doomed.push_back(e.msg);
    }
    for (Message* m : doomed) remove(*m);
}

FutureEventSet::Entry FutureEventSet::take(std::size_t i) {
    Entry out = std::move(heap_[i]);
    out.msg->heapIndex_ = Message::kNotScheduled;
    out.msg->fes_ = nullptr;
    Entry last = std::move(heap_.back());
    heap_.pop_back();
    if (i < heap_.size()) {
        place(i, std::move(last));
        if (i > 0 && before(*heap_[i].msg, *heap_[(i - 1) / 2].msg)) {
            siftUp(i);
        } else {
            siftDown(i);
        }
    }
    return out;
}

void FutureEventSet::place(std::size_t i, Entry e) {
    e.msg->heapIndex_ = i;
    heap_[i] = std::move(e);
}

void FutureEventSet::siftUp(std::size_t i) {
    Entry moving = std::move(heap_[i]);
    while (i > 0) {
        const std::size_t parent = (i - 1) / 2;
        if (!before(*moving.msg, *heap_[parent].msg)) break;
        place(i, std::move(heap_[parent]));
        i = parent;
    }
    place(i, std::move(moving));
}

void FutureEventSet::siftDown(std::size_t i) {
    const std::size_t n = heap_.size();
    Entry moving = std::move(heap_[i]);
    while (true) {
        std::size_t child = 2 * i + 1;
        if (child >= n) break;
        if (child + 1 < n && before(*heap_[child + 1].msg, *heap_[child].msg)) ++child;
        if (!before(*heap_[child].msg, *moving.msg)) break;
        place(i, std::move(heap_[child]));
        i = child;
    }
    place(i, std::move(moving));
}

}  // namespace sbsim::kernel
