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
    // Taken out first: an owned message's destructor then finds itself unscheduled.
    std::vector<Message*> all;
    all.reserve(size_);
    for (const Entry& e : heap_) all.push_back(e.msg);
    heap_.clear();
    for (std::size_t l = 0; l < laneCount_; ++l) {
        Lane& lane = lanes_[l];
        for (std::uint64_t p = lane.head; p < lane.tail; ++p) {
            if (lane.at(p).msg != nullptr) all.push_back(lane.at(p).msg);
        }
        lane.head = lane.tail = 0;
        lane.live = 0;
    }
    size_ = 0;
    next_ = kNone;
    for (Message* m : all) {
        m->heapIndex_ = Message::kNotScheduled;
        m->fes_ = nullptr;
    }
    for (Message* m : all) {
        if (m->ownedBySet_) delete m;
    }
}

FutureEventSet::Lane* FutureEventSet::laneFor(SimTime::rep delay, int priority, SimTime at) {
    Lane* free = nullptr;
    for (std::size_t l = 0; l < laneCount_; ++l) {
        Lane& lane = lanes_[l];
        if (lane.delay == delay && lane.priority == priority) {
            // Sorted after the lane's last (a later insertion: a larger order) or not at all.
            if (lane.live == 0 || at >= lane.at(lane.tail - 1).at) return &lane;
            return nullptr;
        }
        if (free == nullptr && lane.live == 0) free = &lane;
    }
    // A delay seen once (a random phase) stays in the heap; one that recurs gets a lane.
    const std::pair<SimTime::rep, int> key{delay, priority};
    bool recurs = false;
    for (const auto& r : recent_) recurs = recurs || r == key;
    if (!recurs) {
        recent_[recentNext_] = key;
        recentNext_ = (recentNext_ + 1) % kRecent;
        return nullptr;
    }
    if (free == nullptr && laneCount_ < kLanes) free = &lanes_[laneCount_++];
    if (free == nullptr) return nullptr;
    free->delay = delay;
    free->priority = priority;
    free->head = free->tail = 0;
    return free;
}

void FutureEventSet::insert(Message& msg, SimTime at, Module* target) {
    if (msg.isScheduled()) throw std::logic_error("message '" + msg.name() + "' is already scheduled");
    msg.arrival_ = at;
    msg.target_ = target;
    msg.insertionOrder_ = nextInsertion_++;
    msg.fes_ = this;
    msg.ownedBySet_ = false;
    ++size_;
    SimTime::rep delay = 0;
    Lane* lane = __builtin_sub_overflow(at.raw(), clock_.raw(), &delay) ? nullptr : laneFor(delay, msg.priority_, at);
    if (lane != nullptr) {
        if (lane->tail - lane->head == lane->ring.size()) {
            // Full: twice as long, each position at its place in the new ring.
            std::vector<Slot> ring(lane->ring.empty() ? 64 : 2 * lane->ring.size());
            for (std::uint64_t p = lane->head; p < lane->tail; ++p) ring[p & (ring.size() - 1)] = lane->at(p);
            lane->ring.swap(ring);
        }
        const std::uint64_t position = lane->tail++;
        lane->at(position) = Slot{at, msg.insertionOrder_, &msg, target};
        const auto index = static_cast<std::size_t>(lane - lanes_.data());
        msg.heapIndex_ = kInLane | (index << kLaneShift) | (position & kPositionMask);
        // A lane's new head may come first; a slot behind its head cannot.
        if (lane->live++ == 0) next_ = kUnknown;
        return;
    }
    heap_.push_back(Entry{at, msg.insertionOrder_, msg.priority_, &msg});
    msg.heapIndex_ = heap_.size() - 1;
    siftUp(heap_.size() - 1);
    if (msg.heapIndex_ == 0) next_ = kUnknown;
}

void FutureEventSet::insert(std::unique_ptr<Message> msg, SimTime at, Module* target) {
    Message& m = *msg;
    insert(m, at, target);
    m.ownedBySet_ = true;
    msg.release();  // the set frees it (remove, clear) or hands it back (pop)
}

void FutureEventSet::remove(Message& msg) {
    if (msg.fes_ != this || !msg.isScheduled()) return;
    const std::size_t where = msg.heapIndex_;
    Message& m = (where & kInLane) != 0 ? takeFromLane((where & ~kInLane) >> kLaneShift, where & kPositionMask)
                                        : takeFromHeap(where);
    next_ = kUnknown;
    // An owned message being cancelled dies here, as it would have after delivery.
    if (m.ownedBySet_) delete &m;
}

Message& FutureEventSet::pop(std::unique_ptr<Message>& owned) {
    const int n = next();
    if (n == kNone) throw std::logic_error("pop from an empty future-event set");
    Message& m = n == kHeap ? takeFromHeap(0) : takeFromLane(static_cast<std::size_t>(n), lanes_[n].head);
    clock_ = m.arrival_;
    next_ = kUnknown;
    prefetchNext();
    if (m.ownedBySet_) owned.reset(&m);
    return m;
}

int FutureEventSet::next() const {
    if (next_ != kUnknown) return next_;
    int best = heap_.empty() ? kNone : kHeap;
    Entry key = heap_.empty() ? Entry{} : heap_.front();
    for (std::size_t l = 0; l < laneCount_; ++l) {
        const Lane& lane = lanes_[l];
        if (lane.live == 0) continue;
        const Slot& head = lane.at(lane.head);
        const Entry candidate{head.at, head.order, lane.priority, head.msg};
        if (best == kNone || before(candidate, key)) {
            best = static_cast<int>(l);
            key = candidate;
        }
    }
    next_ = best;
    return best;
}

FutureEventSet::Entry FutureEventSet::nextSlot() const {
    const int n = next();
    if (n == kNone) throw std::logic_error("peek into an empty future-event set");
    if (n == kHeap) return heap_.front();
    const Lane& lane = lanes_[static_cast<std::size_t>(n)];
    const Slot& head = lane.at(lane.head);
    return Entry{head.at, head.order, lane.priority, head.msg};
}

void FutureEventSet::prefetchNext() const {
    const int n = next();
    if (n == kNone) return;
    if (n == kHeap) {
        __builtin_prefetch(heap_.front().msg);
        return;
    }
    const Lane& lane = lanes_[static_cast<std::size_t>(n)];
    const Slot& head = lane.at(lane.head);
    __builtin_prefetch(head.msg);
    __builtin_prefetch(head.target);  // its vtable, read to hand the message over
}

void FutureEventSet::removeAllFor(const Module& target) {
    // Collect first: removing re-orders the heap under an index loop.
    std::vector<Message*> doomed;
    for (const Entry& e : heap_) {
        if (e.msg->target_ == &target) doomed.push_back(e.msg);
    }
    for (std::size_t l = 0; l < laneCount_; ++l) {
        const Lane& lane = lanes_[l];
        for (std::uint64_t p = lane.head; p < lane.tail; ++p) {
            const Slot& s = lane.at(p);
            if (s.msg != nullptr && s.target == &target) doomed.push_back(s.msg);
        }
    }
    for (Message* m : doomed) remove(*m);
}

Message& FutureEventSet::takeFromLane(std::size_t l, std::uint64_t position) {
    Lane& lane = lanes_[l];
    Slot& slot = lane.at(position);
    Message& out = *slot.msg;
    out.heapIndex_ = Message::kNotScheduled;
    out.fes_ = nullptr;
    slot.msg = nullptr;
    --lane.live;
    --size_;
    // The head stays on a live slot (or the tail): cancelled ones behind it are skipped once.
    while (lane.head < lane.tail && lane.at(lane.head).msg == nullptr) ++lane.head;
    return out;
}

Message& FutureEventSet::takeFromHeap(std::size_t i) {
    Message& out = *heap_[i].msg;
    out.heapIndex_ = Message::kNotScheduled;
    out.fes_ = nullptr;
    --size_;
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
