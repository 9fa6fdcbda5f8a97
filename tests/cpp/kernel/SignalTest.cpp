#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "ThrownMessage.h"
#include "sbsim/kernel/Module.h"
#include "sbsim/kernel/Signal.h"
#include "sbsim/kernel/Simulation.h"

namespace sbsim::kernel {
namespace {

/// Records each signal it receives as "source/signal=value" (with a type tag).
class Recording : public Listener {
public:
    explicit Recording(std::string tag = "") : tag_(std::move(tag)) {}
    std::vector<std::string> got;
    std::function<void(Module&, SignalId)> onAny;

    void receiveSignal(Module& source, SignalId id, std::int64_t value) override {
        record(source, id, "i:" + std::to_string(value));
    }
    void receiveSignal(Module& source, SignalId id, double value) override {
        record(source, id, "d:" + std::to_string(value));
    }
    void receiveSignal(Module& source, SignalId id, std::string_view value) override {
        record(source, id, "s:" + std::string(value));
    }
    void receiveSignal(Module& source, SignalId id, const Object& value) override;

private:
    void record(Module& source, SignalId id, const std::string& value) {
        got.push_back(tag_ + source.name() + "/" + signalName(id) + "=" + value);
        if (onAny) onAny(source, id);
    }
    std::string tag_;
};

struct Payload : Object {
    explicit Payload(int v) : value(v) {}
    int value;
};
struct OtherPayload : Object {};

void Recording::receiveSignal(Module& source, SignalId id, const Object& value) {
    const auto* p = dynamic_cast<const Payload*>(&value);
    record(source, id, p != nullptr ? "o:" + std::to_string(p->value) : std::string("o:?"));
}

/// A module whose emit() the tests can call.
class Emitter : public Module {
public:
    using Module::emit;
    using Module::Module;
};

TEST(Signal, RegisterSignalGivesOneStableIdPerName) {
    const SignalId a = registerSignal("test.alpha");
    const SignalId b = registerSignal("test.beta");
    EXPECT_NE(a, b);
    EXPECT_GE(a, 0);
    EXPECT_EQ(registerSignal("test.alpha"), a);
    EXPECT_EQ(registerSignal(std::string("test.") + "beta"), b);
    EXPECT_EQ(signalName(a), "test.alpha");
    EXPECT_EQ(signalName(b), "test.beta");
    EXPECT_THROW(signalName(-1), std::out_of_range);
    EXPECT_THROW(signalName(1'000'000), std::out_of_range);
    EXPECT_EQ(testing_support::thrownMessage([] { signalName(-1); }), "unknown signal id -1");
}

TEST(Signal, SignalNameStaysValidWhileMoreSignalsAreRegistered) {
    const std::string& name = signalName(registerSignal("test.early-signal-with-a-long-name-beyond-sso"));
    for (int i = 0; i < 2000; ++i) registerSignal("test.filler." + std::to_string(i));
    EXPECT_EQ(name, "test.early-signal-with-a-long-name-beyond-sso");
}

TEST(Signal, EmitReachesTheOverloadOfItsValueType) {
    const SignalId sig = registerSignal("test.values");
    Simulation sim;
    auto& m = sim.emplaceModule<Emitter>("m");
    Recording r;
    m.subscribe(sig, r);
    m.emit(sig, 42);                        // int -> int64
    m.emit(sig, std::int64_t{1} << 40);     // int64
    m.emit(sig, 2.5);                       // double
    m.emit(sig, "text");                    // const char* -> string_view
    m.emit(sig, std::string_view("view"));  // string_view
    m.emit(sig, static_cast<const Object&>(Payload(7)));
    EXPECT_EQ(r.got, (std::vector<std::string>{"m/test.values=i:42", "m/test.values=i:1099511627776",
                                               "m/test.values=d:2.500000", "m/test.values=s:text",
                                               "m/test.values=s:view", "m/test.values=o:7"}));
}

TEST(Signal, ModuleLocalAndSimulationWideListeners) {
    const SignalId sig = registerSignal("test.local-global");
    const SignalId other = registerSignal("test.local-global-other");
    Simulation sim;
    auto& a = sim.emplaceModule<Emitter>("a");
    auto& b = sim.emplaceModule<Emitter>("b");
    Recording local("local:"), global("global:"), unrelated("unrelated:");
    a.subscribe(sig, local);
    sim.subscribe(sig, global);
    sim.subscribe(other, unrelated);
    a.emit(sig, 1);  // local first, then global
    b.emit(sig, 2);  // only global: local listens to a
    a.emit(registerSignal("test.nobody-listens"), 3);
    EXPECT_EQ(local.got, (std::vector<std::string>{"local:a/test.local-global=i:1"}));
    EXPECT_EQ(global.got,
              (std::vector<std::string>{"global:a/test.local-global=i:1", "global:b/test.local-global=i:2"}));
    EXPECT_TRUE(unrelated.got.empty());

    // Order across tables: the module's listeners before the simulation's.
    std::vector<std::string> order;
    local.onAny = [&](Module&, SignalId) { order.push_back("local"); };
    global.onAny = [&](Module&, SignalId) { order.push_back("global"); };
    a.emit(sig, 4);
    EXPECT_EQ(order, (std::vector<std::string>{"local", "global"}));
}

TEST(Signal, SubscribingTwiceNotifiesOnceAndUnsubscribeStops) {
    const SignalId sig = registerSignal("test.unsubscribe");
    Simulation sim;
    auto& m = sim.emplaceModule<Emitter>("m");
    Recording first("1:"), second("2:");
    m.subscribe(sig, first);
    m.subscribe(sig, first);
    m.subscribe(sig, second);
    m.emit(sig, 1);
    m.unsubscribe(sig, first);
    m.unsubscribe(sig, first);                            // no longer subscribed: a no-op
    m.unsubscribe(registerSignal("test.never"), second);  // never subscribed: a no-op
    m.emit(sig, 2);
    EXPECT_EQ(first.got, (std::vector<std::string>{"1:m/test.unsubscribe=i:1"}));
    EXPECT_EQ(second.got, (std::vector<std::string>{"2:m/test.unsubscribe=i:1", "2:m/test.unsubscribe=i:2"}));
    EXPECT_FALSE(sim.signals().hasListeners(sig));
    EXPECT_THROW(m.subscribe(-1, first), std::invalid_argument);
}

TEST(Signal, HasListeners) {
    const SignalId sig = registerSignal("test.has-listeners");
    SignalTable table;
    EXPECT_FALSE(table.hasListeners(sig));
    EXPECT_FALSE(table.hasListeners(-1));
    {
        Recording r;
        table.subscribe(sig, r);
        EXPECT_TRUE(table.hasListeners(sig));
        table.unsubscribe(sig, r);
        EXPECT_FALSE(table.hasListeners(sig));
        table.subscribe(sig, r);
    }
    EXPECT_FALSE(table.hasListeners(sig));  // the destroyed listener left
}

TEST(Signal, ListenerDestroyedBeforeTheTable) {
    const SignalId sig = registerSignal("test.listener-first");
    Simulation sim;
    auto& m = sim.emplaceModule<Emitter>("m");
    Recording survivor;
    {
        Recording shortLived;
        m.subscribe(sig, shortLived);
        sim.subscribe(sig, shortLived);
        m.subscribe(sig, survivor);
    }
    m.emit(sig, 1);  // must not call the dead listener (a crash or a sanitizer report otherwise)
    EXPECT_EQ(survivor.got.size(), 1u);
    EXPECT_FALSE(sim.signals().hasListeners(sig));
}

TEST(Signal, TableDestroyedBeforeTheListener) {
    const SignalId sig = registerSignal("test.table-first");
    Recording r;
    {
        Simulation sim;
        auto& m = sim.emplaceModule<Emitter>("m");
        m.subscribe(sig, r);
        sim.subscribe(sig, r);
        m.emit(sig, 1);
        auto& n = sim.emplaceModule<Emitter>("n");
        n.subscribe(sig, r);
        sim.removeModule(n);  // n's table goes first
        m.emit(sig, 2);
    }
    // r's destructor would unsubscribe from the dead tables if they had not told it.
    EXPECT_EQ(r.got.size(), 4u);
    SignalTable later;
    later.subscribe(sig, r);
    EXPECT_TRUE(later.hasListeners(sig));
}

TEST(Signal, SubscribingDuringNotificationTakesEffectNextTime) {
    const SignalId sig = registerSignal("test.subscribe-during");
    const SignalId other = registerSignal("test.subscribe-during-other");
    Simulation sim;
    auto& m = sim.emplaceModule<Emitter>("m");
    Recording first("1:"), late("late:");
    std::vector<std::unique_ptr<Recording>> spawned;
    first.onAny = [&](Module& source, SignalId id) {
        if (id != sig) return;
        source.subscribe(sig, late);
        source.subscribe(other, late);  // grows the table while it is iterated
        // Many new listeners: the list reallocates under the notification.
        for (int i = 0; i < 50; ++i) {
            spawned.push_back(std::make_unique<Recording>("x:"));
            source.subscribe(sig, *spawned.back());
        }
    };
    m.subscribe(sig, first);
    m.emit(sig, 1);
    EXPECT_TRUE(late.got.empty());
    first.onAny = nullptr;
    m.emit(sig, 2);
    EXPECT_EQ(late.got, (std::vector<std::string>{"late:m/test.subscribe-during=i:2"}));
    EXPECT_EQ(spawned.front()->got.size(), 1u);
    EXPECT_EQ(spawned.back()->got.size(), 1u);
}

TEST(Signal, ListenerUnsubscribedDuringNotificationIsNotCalledAnymore) {
    const SignalId sig = registerSignal("test.unsubscribe-during");
    Simulation sim;
    auto& m = sim.emplaceModule<Emitter>("m");
    Recording first("1:"), second("2:"), third("3:");
    first.onAny = [&](Module& source, SignalId) { source.unsubscribe(sig, second); };
    m.subscribe(sig, first);
    m.subscribe(sig, second);
    m.subscribe(sig, third);
    m.emit(sig, 1);
    EXPECT_EQ(first.got.size(), 1u);
    EXPECT_TRUE(second.got.empty());
    EXPECT_EQ(third.got.size(), 1u);
    // Unsubscribing oneself while being notified, and the table stays consistent afterwards.
    third.onAny = [&](Module& source, SignalId) { source.unsubscribe(sig, third); };
    m.emit(sig, 2);
    m.emit(sig, 3);
    EXPECT_EQ(first.got.size(), 3u);
    EXPECT_EQ(third.got.size(), 2u);
    first.onAny = nullptr;
    m.subscribe(sig, second);
    m.emit(sig, 4);
    EXPECT_EQ(second.got, (std::vector<std::string>{"2:m/test.unsubscribe-during=i:4"}));
}

TEST(Signal, ListenerDestroyedDuringNotificationIsNotCalled) {
    // E.g. a listener to "vehicle arrived" that removes the module of that vehicle, which itself
    // listened to the same signal.
    const SignalId sig = registerSignal("test.destroyed-during");
    Simulation sim;
    auto& m = sim.emplaceModule<Emitter>("m");
    Recording killer("killer:");
    auto victim = std::make_unique<Recording>("victim:");
    int victimCalls = 0;
    victim->onAny = [&](Module&, SignalId) { ++victimCalls; };
    killer.onAny = [&](Module&, SignalId) { victim.reset(); };
    sim.subscribe(sig, killer);
    sim.subscribe(sig, *victim);
    m.emit(sig, 1);
    EXPECT_EQ(victim, nullptr);
    EXPECT_EQ(victimCalls, 0);
    m.emit(sig, 2);
    EXPECT_EQ(killer.got.size(), 2u);
}

TEST(Signal, UnsubscribingInANestedNotification) {
    const SignalId outer = registerSignal("test.nested-outer");
    const SignalId inner = registerSignal("test.nested-inner");
    Simulation sim;
    auto& m = sim.emplaceModule<Emitter>("m");
    Recording relay("relay:"), sink("sink:");
    relay.onAny = [&](Module& source, SignalId id) {
        if (id == outer) static_cast<Emitter&>(source).emit(inner, 9);
    };
    // Leaves `outer` while the table notifies `inner` inside a notification of `outer`.
    sink.onAny = [&](Module& source, SignalId id) {
        if (id == inner) source.unsubscribe(outer, sink);
    };
    m.subscribe(outer, relay);
    m.subscribe(outer, sink);
    m.subscribe(inner, sink);
    m.emit(outer, 1);
    EXPECT_EQ(sink.got, (std::vector<std::string>{"sink:m/test.nested-inner=i:9"}));
    m.emit(outer, 2);
    m.emit(inner, 3);
    EXPECT_EQ(sink.got, (std::vector<std::string>{"sink:m/test.nested-inner=i:9", "sink:m/test.nested-inner=i:9",
                                                  "sink:m/test.nested-inner=i:3"}));
    EXPECT_EQ(relay.got, (std::vector<std::string>{"relay:m/test.nested-outer=i:1", "relay:m/test.nested-outer=i:2"}));
}

TEST(Signal, ListenerThatThrowsLeavesTheTableUsable) {
    const SignalId sig = registerSignal("test.throwing");
    Simulation sim;
    auto& m = sim.emplaceModule<Emitter>("m");
    Recording thrower("t:"), other("o:");
    thrower.onAny = [&](Module& source, SignalId) {
        source.unsubscribe(sig, other);
        throw std::runtime_error("listener failed");
    };
    m.subscribe(sig, thrower);
    m.subscribe(sig, other);
    EXPECT_THROW(m.emit(sig, 1), std::runtime_error);
    thrower.onAny = nullptr;
    m.emit(sig, 2);
    m.subscribe(sig, other);
    m.emit(sig, 3);
    EXPECT_EQ(thrower.got.size(), 3u);
    EXPECT_EQ(other.got, (std::vector<std::string>{"o:m/test.throwing=i:3"}));

    // The same on a bare table: after the throw, unsubscribing really empties it.
    SignalTable table;
    Emitter source("source");
    thrower.onAny = [&](Module&, SignalId) { throw std::runtime_error("listener failed"); };
    table.subscribe(sig, thrower);
    table.subscribe(sig, other);
    EXPECT_THROW(table.notify(source, sig, std::int64_t{4}), std::runtime_error);
    table.unsubscribe(sig, thrower);
    table.unsubscribe(sig, other);
    EXPECT_FALSE(table.hasListeners(sig));
}

}  // namespace
}  // namespace sbsim::kernel
