#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "TestPrinters.h"
#include "sbsim/kernel/FutureEventSet.h"
#include "sbsim/kernel/Module.h"

namespace sbsim::kernel {
namespace {

SimTime ms(SimTime::rep n) { return SimTime::fromMilliseconds(n); }

/// Counts its destructions, to observe who frees owned messages and when.
class CountedMessage : public Message {
public:
    CountedMessage(std::string name, int& destroyed) : Message(std::move(name)), destroyed_(destroyed) {}
    ~CountedMessage() override { ++destroyed_; }

private:
    int& destroyed_;
};

/// Pops everything, returning the names in delivery order.
std::vector<std::string> drain(FutureEventSet& fes) {
    std::vector<std::string> names;
    while (!fes.empty()) {
        std::unique_ptr<Message> owned;
        names.push_back(fes.pop(owned).name());
    }
    return names;
}

/// A reference model's entry: the set's total order (time, priority, insertion order) in a std::set.
struct Key {
    SimTime at;
    int priority;
    std::uint64_t order;
    Message* msg;
    auto operator<=>(const Key&) const = default;
};

class FutureEventSetTest : public ::testing::Test {
protected:
    Module a_{"a"};
    Module b_{"b"};
};

TEST_F(FutureEventSetTest, EmptySet) {
    FutureEventSet fes;
    EXPECT_TRUE(fes.empty());
    EXPECT_EQ(fes.size(), 0u);
    std::unique_ptr<Message> owned;
    EXPECT_THROW(fes.pop(owned), std::logic_error);
}

TEST_F(FutureEventSetTest, OrdersByTimeThenPriorityThenInsertion) {
    FutureEventSet fes;
    Message late("late"), early("early"), tieFirst("tie-first"), tieSecond("tie-second"), urgent("urgent"),
        lazy("lazy");
    urgent.setPriority(-5);
    lazy.setPriority(5);
    fes.insert(late, ms(30), &a_);
    fes.insert(lazy, ms(20), &a_);
    fes.insert(tieFirst, ms(20), &a_);
    fes.insert(early, ms(10), &b_);
    fes.insert(tieSecond, ms(20), &b_);
    fes.insert(urgent, ms(20), &b_);
    EXPECT_EQ(fes.size(), 6u);
    EXPECT_EQ(fes.peek().name(), "early");
    EXPECT_EQ(drain(fes), (std::vector<std::string>{"early", "urgent", "tie-first", "tie-second", "lazy", "late"}));
    EXPECT_FALSE(late.isScheduled());
}

TEST_F(FutureEventSetTest, ScheduledMessageKnowsItsArrival) {
    FutureEventSet fes;
    Message m("m");
    EXPECT_FALSE(m.isScheduled());
    fes.insert(m, ms(5), &b_);
    EXPECT_TRUE(m.isScheduled());
    EXPECT_EQ(m.arrivalTime(), ms(5));
    EXPECT_EQ(m.arrivalModule(), &b_);
    std::unique_ptr<Message> owned;
    EXPECT_EQ(&fes.pop(owned), &m);
    EXPECT_EQ(owned, nullptr);  // not the set's to free
    EXPECT_FALSE(m.isScheduled());
    // It can be scheduled again once delivered.
    fes.insert(m, ms(6), &a_);
    EXPECT_TRUE(m.isScheduled());
}

TEST_F(FutureEventSetTest, DoubleInsertAndPriorityChangeWhileScheduledThrow) {
    FutureEventSet fes;
    Message m("m");
    fes.insert(m, ms(1), &a_);
    EXPECT_THROW(fes.insert(m, ms(2), &a_), std::logic_error);
    EXPECT_THROW(m.setPriority(3), std::logic_error);
    EXPECT_EQ(fes.size(), 1u);
    EXPECT_EQ(m.arrivalTime(), ms(1));
    FutureEventSet other;
    EXPECT_THROW(other.insert(m, ms(2), &a_), std::logic_error);
    EXPECT_TRUE(other.empty());
}

TEST_F(FutureEventSetTest, CancelInTheMiddle) {
    FutureEventSet fes;
    std::vector<std::unique_ptr<Message>> msgs;
    for (int i = 0; i < 9; ++i) {
        msgs.push_back(std::make_unique<Message>("m" + std::to_string(i)));
        fes.insert(*msgs.back(), ms(i), &a_);
    }
    fes.remove(*msgs[4]);
    fes.remove(*msgs[7]);
    fes.remove(*msgs[4]);  // no longer scheduled: a no-op
    EXPECT_FALSE(msgs[4]->isScheduled());
    EXPECT_EQ(fes.size(), 7u);
    EXPECT_EQ(drain(fes), (std::vector<std::string>{"m0", "m1", "m2", "m3", "m5", "m6", "m8"}));
}

TEST_F(FutureEventSetTest, RemoveIgnoresAMessageOfAnotherSet) {
    FutureEventSet fes, other;
    Message mine("mine"), theirs("theirs");
    fes.insert(mine, ms(1), &a_);
    other.insert(theirs, ms(1), &a_);
    fes.remove(theirs);
    EXPECT_TRUE(theirs.isScheduled());
    EXPECT_EQ(other.size(), 1u);
    EXPECT_EQ(fes.size(), 1u);
}

TEST_F(FutureEventSetTest, DestroyingAScheduledMessageUnschedulesIt) {
    FutureEventSet fes;
    Message first("first"), last("last");
    fes.insert(first, ms(1), &a_);
    {
        Message middle("middle");
        fes.insert(middle, ms(2), &a_);
        Message alsoMiddle("also-middle");
        fes.insert(alsoMiddle, ms(2), &a_);
        EXPECT_EQ(fes.size(), 3u);
    }
    fes.insert(last, ms(3), &a_);
    EXPECT_EQ(fes.size(), 2u);
    EXPECT_EQ(drain(fes), (std::vector<std::string>{"first", "last"}));
}

TEST_F(FutureEventSetTest, OwnedMessagesAreFreedWhenRemovedPoppedOrLeftOver) {
    int destroyed = 0;
    auto fes = std::make_unique<FutureEventSet>();
    auto cancelled = std::make_unique<CountedMessage>("cancelled", destroyed);
    Message& cancelledRef = *cancelled;
    fes->insert(std::move(cancelled), ms(2), &a_);
    fes->insert(std::make_unique<CountedMessage>("delivered", destroyed), ms(1), &a_);
    fes->insert(std::make_unique<CountedMessage>("left-over", destroyed), ms(3), &a_);
    EXPECT_EQ(destroyed, 0);

    fes->remove(cancelledRef);
    EXPECT_EQ(destroyed, 1);

    {
        std::unique_ptr<Message> owned;
        Message& m = fes->pop(owned);
        EXPECT_EQ(m.name(), "delivered");
        ASSERT_NE(owned, nullptr);  // the caller now owns it
        EXPECT_EQ(owned.get(), &m);
        EXPECT_EQ(destroyed, 1);
    }
    EXPECT_EQ(destroyed, 2);

    fes.reset();
    EXPECT_EQ(destroyed, 3);
}

TEST_F(FutureEventSetTest, MessagesOutliveTheSetSafely) {
    Message survivor("survivor");
    {
        FutureEventSet fes;
        fes.insert(survivor, ms(1), &a_);
    }
    EXPECT_FALSE(survivor.isScheduled());
    // Usable in a new set; its destructor must not touch the dead one.
    FutureEventSet fes;
    fes.insert(survivor, ms(2), &a_);
    EXPECT_EQ(fes.size(), 1u);
}

TEST_F(FutureEventSetTest, RemoveAllForDropsOnlyThatTargetsMessages) {
    int destroyed = 0;
    FutureEventSet fes;
    std::vector<std::unique_ptr<Message>> timers;
    for (int i = 0; i < 20; ++i) {
        Module* target = i % 3 == 0 ? &a_ : &b_;
        const std::string name = std::string(target == &a_ ? "a" : "b") + std::to_string(i);
        if (i % 2 == 0) {
            timers.push_back(std::make_unique<Message>(name));
            fes.insert(*timers.back(), ms(100 - i), target);
        } else {
            fes.insert(std::make_unique<CountedMessage>(name, destroyed), ms(100 - i), target);
        }
    }
    // a: i = 0, 3, ..., 18 (7 messages, of which 3 owned: 3, 9, 15).
    fes.removeAllFor(a_);
    EXPECT_EQ(destroyed, 3);
    EXPECT_EQ(fes.size(), 13u);
    for (const auto& t : timers) EXPECT_EQ(t->isScheduled(), t->name()[0] == 'b') << t->name();
    std::vector<std::string> expected;
    for (int i = 19; i >= 0; --i) {
        if (i % 3 != 0) expected.push_back("b" + std::to_string(i));
    }
    EXPECT_EQ(drain(fes), expected);
    EXPECT_EQ(destroyed, 10);
}

// Random inserts, cancels, destructions and pops against a reference ordered set.
TEST_F(FutureEventSetTest, MatchesAReferenceModelUnderRandomOperations) {
    std::mt19937_64 rng(20240611);
    const auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };

    FutureEventSet fes;
    std::set<Key> reference;
    std::uint64_t order = 0;
    // Pool of caller-owned messages; owned ones are tracked by raw pointer until they leave.
    std::vector<std::unique_ptr<Message>> pool;
    for (int i = 0; i < 300; ++i) pool.push_back(std::make_unique<Message>("p" + std::to_string(i)));
    std::vector<Message*> ownedLive;
    int ownedDestroyed = 0;
    int ownedCreated = 0;
    SimTime now;
    const auto keyOf = [&](Message* m) {
        return std::find_if(reference.begin(), reference.end(), [m](const Key& k) { return k.msg == m; });
    };

    int pops = 0;
    for (int step = 0; step < 20'000; ++step) {
        const int op = pick(0, 99);
        if (op < 40) {  // schedule a pool message (few distinct times and priorities: many ties)
            Message& m = *pool[pick(0, static_cast<int>(pool.size()) - 1)];
            if (m.isScheduled()) continue;
            const SimTime at = now + ms(pick(0, 20));
            m.setPriority(pick(-2, 2));
            fes.insert(m, at, &a_);
            reference.insert({at, m.priority(), order++, &m});
        } else if (op < 55) {  // hand over an owned message
            auto m = std::make_unique<CountedMessage>("o" + std::to_string(ownedCreated++), ownedDestroyed);
            m->setPriority(pick(-2, 2));
            const SimTime at = now + ms(pick(0, 20));
            Message* raw = m.get();
            reference.insert({at, raw->priority(), order++, raw});
            ownedLive.push_back(raw);
            fes.insert(std::move(m), at, &b_);
        } else if (op < 65) {  // cancel something scheduled (pool or owned)
            if (reference.empty()) continue;
            auto it = std::next(reference.begin(), pick(0, static_cast<int>(reference.size()) - 1));
            Message* m = it->msg;
            reference.erase(it);
            std::erase(ownedLive, m);
            fes.remove(*m);
        } else if (op == 65 && pick(0, 9) == 0) {  // a module goes: everything addressed to it
            Module& target = pick(0, 1) == 0 ? a_ : b_;
            for (auto it = reference.begin(); it != reference.end();) {
                if (it->msg->arrivalModule() == &target) {
                    std::erase(ownedLive, it->msg);
                    it = reference.erase(it);
                } else {
                    ++it;
                }
            }
            fes.removeAllFor(target);
        } else if (op < 68) {  // destroy a scheduled pool message outright
            const int i = pick(0, static_cast<int>(pool.size()) - 1);
            if (!pool[i]->isScheduled()) continue;
            reference.erase(keyOf(pool[i].get()));
            pool[i] = std::make_unique<Message>("p-new" + std::to_string(step));
        } else {  // deliver the next event
            ASSERT_EQ(fes.empty(), reference.empty());
            if (reference.empty()) continue;
            const Key expected = *reference.begin();
            reference.erase(reference.begin());
            ASSERT_EQ(&fes.peek(), expected.msg) << "step " << step;
            std::unique_ptr<Message> owned;
            Message& got = fes.pop(owned);
            ASSERT_EQ(&got, expected.msg) << "step " << step;
            ASSERT_EQ(got.arrivalTime(), expected.at);
            ASSERT_FALSE(got.isScheduled());
            const bool wasOwned = std::erase(ownedLive, &got) == 1;
            ASSERT_EQ(owned != nullptr, wasOwned);
            now = expected.at;
            ++pops;
        }
        ASSERT_EQ(fes.size(), reference.size()) << "step " << step;
        ASSERT_EQ(ownedDestroyed, ownedCreated - static_cast<int>(ownedLive.size())) << "step " << step;
    }
    EXPECT_GT(pops, 5000);  // the random mix really exercised delivery
    // Whatever is left comes out in reference order.
    for (const Key& k : reference) {
        std::unique_ptr<Message> owned;
        ASSERT_EQ(&fes.pop(owned), k.msg);
    }
    EXPECT_TRUE(fes.empty());
}

// Many events at once (a city's timers and frames): the heap is several levels deep and most
// times are shared, so the order rests on priority and insertion; interleaved pops and inserts.
TEST_F(FutureEventSetTest, DeepHeapDeliversInKeyOrder) {
    struct Key {
        SimTime at;
        int priority;
        std::uint64_t order;
        auto operator<=>(const Key&) const = default;
    };
    std::mt19937_64 rng(7);
    FutureEventSet fes;
    std::vector<std::unique_ptr<Message>> pool;
    std::vector<Key> keys;  // per pool index, the key it was scheduled with
    std::uint64_t order = 0;
    SimTime now;
    const auto schedule = [&](std::size_t i) {
        // Never at `now`: what comes later is then after every key delivered so far.
        const SimTime at = now + ms(1 + static_cast<SimTime::rep>(rng() % 50));
        pool[i]->setPriority(static_cast<int>(rng() % 3) - 1);
        keys[i] = {at, pool[i]->priority(), order++};
        fes.insert(*pool[i], at, &a_);
    };
    for (std::size_t i = 0; i < 20'000; ++i) {
        pool.push_back(std::make_unique<Message>(std::to_string(i)));
        keys.emplace_back();
        schedule(i);
    }
    Key last{SimTime::zero(), -2, 0};
    for (int k = 0; k < 100'000; ++k) {
        std::unique_ptr<Message> owned;
        Message& m = fes.pop(owned);
        const std::size_t i = std::stoul(m.name());
        ASSERT_LT(last, keys[i]) << "pop " << k;
        last = keys[i];
        now = m.arrivalTime();
        if (k % 7 != 0) schedule(i);  // most come back, the heap shrinks slowly
        if (k % 11 == 0 && !fes.empty()) {
            // A cancel from the middle, rescheduled at once: its key is new.
            const std::size_t j = rng() % pool.size();
            if (pool[j]->isScheduled()) {
                fes.remove(*pool[j]);
                schedule(j);
            }
        }
        if (fes.empty()) break;
    }
}

// A city's events: per station a periodic timer (one period, so a lane) and frames a fixed latency
// later (another), stations joining at random phases (the heap), a few timers of another priority
// and of drifting periods, cancels from a lane's middle and head, stations leaving (removeAllFor)
// and timers destroyed while scheduled: delivered in the reference order, and the lanes do serve.
TEST_F(FutureEventSetTest, LanesKeepTheOrderOfARunsTimersAndFrames) {
    std::mt19937_64 rng(28);
    const auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    const SimTime period = ms(100), latency = SimTime::fromNanoseconds(2'000);

    FutureEventSet fes;
    std::set<Key> reference;
    std::uint64_t order = 0;
    std::vector<std::unique_ptr<Module>> stations;
    std::vector<std::unique_ptr<Message>> timers;  // per station
    int frames = 0, framesDestroyed = 0;
    SimTime now = SimTime::fromSeconds(110);  // a run from a saved state: the first delays are long
    const auto schedule = [&](Message& m, SimTime at, Module& target) {
        reference.insert({at, m.priority(), order++, &m});
        fes.insert(m, at, &target);
    };
    const auto join = [&] {
        stations.push_back(std::make_unique<Module>("s" + std::to_string(stations.size())));
        timers.push_back(std::make_unique<Message>(std::to_string(timers.size())));
        if (pick(0, 9) == 0) timers.back()->setPriority(1);  // another priority: a lane of its own
        schedule(*timers.back(), now + SimTime::fromNanoseconds(pick(1, 99'999'999)), *stations.back());
    };
    const auto forget = [&](Message* m) {
        for (auto it = reference.begin(); it != reference.end(); ++it) {
            if (it->msg == m) {
                reference.erase(it);
                return;
            }
        }
    };
    for (int i = 0; i < 300; ++i) join();

    std::size_t mostInLanes = 0;
    int pops = 0;
    for (int step = 0; step < 60'000; ++step) {
        const int op = pick(0, 999);
        if (op < 3) {
            join();
        } else if (op < 5 && !reference.empty()) {  // a station leaves: its timer and the frames to it go
            const std::size_t s = static_cast<std::size_t>(pick(0, static_cast<int>(stations.size()) - 1));
            for (auto it = reference.begin(); it != reference.end();) {
                it = it->msg->arrivalModule() == stations[s].get() ? reference.erase(it) : std::next(it);
            }
            fes.removeAllFor(*stations[s]);
        } else if (op < 15 && !reference.empty()) {  // a cancel anywhere (a lane's middle, often)
            auto it = std::next(reference.begin(), pick(0, static_cast<int>(reference.size()) - 1));
            Message* m = it->msg;
            reference.erase(it);
            fes.remove(*m);
        } else if (op < 17 && !reference.empty()) {  // the very next one cancelled (a lane's head)
            Message* m = reference.begin()->msg;
            reference.erase(reference.begin());
            fes.remove(*m);
        } else if (op < 19) {  // a timer destroyed while scheduled, replaced
            const std::size_t s = static_cast<std::size_t>(pick(0, static_cast<int>(timers.size()) - 1));
            if (!timers[s]->isScheduled()) continue;
            forget(timers[s].get());
            timers[s] = std::make_unique<Message>(std::to_string(s));
            schedule(*timers[s], now + period, *stations[s]);
        } else {  // the next event: a timer sends a frame and comes back a period later
            ASSERT_EQ(fes.empty(), reference.empty());
            if (reference.empty()) continue;
            const Key expected = *reference.begin();
            reference.erase(reference.begin());
            ASSERT_EQ(fes.peekTime(), expected.at) << "step " << step;
            std::unique_ptr<Message> owned;
            Message& got = fes.pop(owned);
            ASSERT_EQ(&got, expected.msg) << "step " << step;
            ASSERT_FALSE(got.isScheduled());
            now = expected.at;
            ++pops;
            if (owned != nullptr) continue;  // a frame, delivered
            const std::size_t s = std::stoul(got.name());
            // Now and then a period that drifts (a story's timer): the heap.
            schedule(got, now + (pick(0, 49) == 0 ? ms(pick(1, 300)) : period), *stations[s]);
            auto frame = std::make_unique<CountedMessage>("frame", framesDestroyed);
            ++frames;
            reference.insert({now + latency, 0, order++, frame.get()});
            fes.insert(std::move(frame), now + latency, stations[pick(0, static_cast<int>(stations.size()) - 1)].get());
        }
        ASSERT_EQ(fes.size(), reference.size()) << "step " << step;
        mostInLanes = std::max(mostInLanes, fes.inLanes());
    }
    EXPECT_GT(pops, 40'000);
    EXPECT_GT(mostInLanes, 250u);  // the periodic timers were in a lane, which grew past its first ring
    for (const Key& k : reference) {
        std::unique_ptr<Message> owned;
        ASSERT_EQ(&fes.pop(owned), k.msg);
    }
    EXPECT_TRUE(fes.empty());
    EXPECT_EQ(framesDestroyed, frames);
}

TEST_F(FutureEventSetTest, ClearEmptiesTheLanesToo) {
    int destroyed = 0;
    FutureEventSet fes;
    std::vector<std::unique_ptr<Message>> timers;
    for (int i = 0; i < 100; ++i) {
        timers.push_back(std::make_unique<Message>(std::to_string(i)));
        fes.insert(*timers.back(), ms(10), &a_);  // one delay, recurring: a lane
        fes.insert(std::make_unique<CountedMessage>("x", destroyed), ms(5), &b_);
    }
    ASSERT_GT(fes.inLanes(), 150u);
    fes.clear();
    EXPECT_TRUE(fes.empty());
    EXPECT_EQ(fes.inLanes(), 0u);
    EXPECT_EQ(destroyed, 100);
    for (const auto& t : timers) EXPECT_FALSE(t->isScheduled());
    fes.insert(*timers[3], ms(4), &a_);  // usable again
    fes.insert(*timers[4], ms(4), &a_);
    EXPECT_EQ(drain(fes), (std::vector<std::string>{"3", "4"}));
}

TEST_F(FutureEventSetTest, ClearFreesOwnedAndUnschedulesTheRest) {
    int destroyed = 0;
    FutureEventSet fes;
    Message timer("timer");
    fes.insert(timer, ms(2), &a_);
    fes.insert(std::make_unique<CountedMessage>("x", destroyed), ms(1), &b_);
    fes.insert(std::make_unique<CountedMessage>("y", destroyed), ms(3), &a_);
    fes.clear();
    EXPECT_TRUE(fes.empty());
    EXPECT_EQ(destroyed, 2);
    EXPECT_FALSE(timer.isScheduled());
    fes.insert(timer, ms(4), &a_);  // usable again
    EXPECT_EQ(drain(fes), (std::vector<std::string>{"timer"}));
}

}  // namespace
}  // namespace sbsim::kernel
