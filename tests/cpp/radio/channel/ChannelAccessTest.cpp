#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "sbsim/kernel/Module.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/CounterRandom.h"
#include "sbsim/radio/channel/ChannelAccess.h"

namespace sbsim::radio {
namespace {

using kernel::SimTime;

struct Frame : V2xMessage {
    std::string_view typeName() const override { return "Frame"; }
    std::size_t byteSize() const override { return 100; }
};

/// A module that hosts channel access on the kernel's clock, as the medium does, and runs a script
/// of calls at given times; it notes when each station's backoff ends and sends at once.
struct Host : kernel::Module, ChannelAccess::Clock {
    explicit Host(const ChannelSettings& settings) : kernel::Module("host"), access(settings, *this) {}
    SimTime now() const override { return simTime(); }
    void schedule(SimTime at, kernel::Message& timer) override { scheduleAt(at, timer); }
    void cancel(kernel::Message& timer) override { cancelEvent(timer); }

    void at(SimTime t, std::function<void()> f) { script.emplace_back(t, std::make_unique<Action>(std::move(f))); }
    void initialize() override {
        access.setSeed(simulation().seed());
        for (auto& [t, a] : script) scheduleAt(t, *a);
    }
    void handleMessage(kernel::Message& msg) override {
        if (msg.kind() == ChannelAccess::kTimerKind) {
            const auto s = static_cast<ChannelAccess::Timer&>(msg).station;
            sent.emplace_back(s, simTime());
            (void)access.take(s);
            return;
        }
        static_cast<Action&>(msg).f();
    }
    struct Action : kernel::Message {
        explicit Action(std::function<void()> fn) : f(std::move(fn)) {}
        std::function<void()> f;
    };
    ChannelAccess access;
    std::vector<std::pair<SimTime, std::unique_ptr<Action>>> script;
    std::vector<std::pair<ChannelAccess::Slot, SimTime>> sent;
};

SimTime us(int u) { return SimTime::fromNanoseconds(1000LL * u); }

/// When station `id` (alone, the channel idle since 0 s, so AIFS has passed) sends a frame queued at 1 ms; with
/// `busyAt`/`idleAt` the channel turns busy and idle again at those times.
SimTime sendTime(const ChannelSettings& settings, const std::string& id, std::optional<SimTime> busyAt = {},
                 std::optional<SimTime> idleAt = {}) {
    kernel::Simulation sim(7, 1);
    auto& host = sim.emplaceModule<Host>(settings);
    host.access.addStation(CounterRandom::keyOf(id));
    host.at(SimTime::fromMilliseconds(1), [&] {
        EXPECT_TRUE(host.access.enqueue(0, std::make_shared<Frame>()));
        host.access.start(0, false);
    });
    if (busyAt) host.at(*busyAt, [&] { host.access.channelBusy(0); });
    if (idleAt) host.at(*idleAt, [&] { host.access.channelIdle(0); });
    sim.run(SimTime::fromSeconds(1));
    EXPECT_EQ(host.sent.size(), 1U);
    return host.sent.empty() ? SimTime::max() : host.sent.front().second;
}

TEST(ChannelAccess, AChannelIdleForAifsAlreadySendsAfterTheBackoff) {
    const ChannelSettings settings;
    std::set<std::int64_t> slots;
    for (int k = 0; k < 40; ++k) {
        const SimTime wait = sendTime(settings, "v" + std::to_string(k)) - SimTime::fromMilliseconds(1);
        ASSERT_GE(wait, SimTime::zero());
        ASSERT_EQ(wait.raw() % settings.slot.raw(), 0);
        slots.insert(wait.raw() / settings.slot.raw());
    }
    EXPECT_LE(*slots.rbegin(), settings.contentionWindow);
    EXPECT_GE(slots.size(), 8U);  // the backoffs spread over the window
}

TEST(ChannelAccess, ABusyChannelFreezesTheBackoffAndSpendsTheIdleSlots) {
    const ChannelSettings settings;
    const SimTime start = SimTime::fromMilliseconds(1);
    int checked = 0;
    for (int k = 0; k < 40; ++k) {
        const std::string id = "v" + std::to_string(k);
        const SimTime free = sendTime(settings, id);
        const auto backoff = (free - start).raw() / settings.slot.raw();
        if (backoff < 3) continue;
        // Busy 2.5 slots into the countdown (two slots spent), idle 1 ms later: AIFS again, then
        // the slots left.
        const SimTime busy = start + settings.slot * 2 + us(6);
        const SimTime idle = busy + SimTime::fromMilliseconds(1);
        EXPECT_EQ(sendTime(settings, id, busy, idle), idle + settings.aifs() + settings.slot * (backoff - 2)) << id;
        ++checked;
    }
    EXPECT_GT(checked, 10);
}

TEST(ChannelAccess, AFullQueueDropsTheFrame) {
    ChannelSettings settings;
    settings.queueLimit = 2;
    kernel::Simulation sim(7, 1);
    auto& host = sim.emplaceModule<Host>(settings);
    host.access.addStation(1);
    EXPECT_TRUE(host.access.enqueue(0, std::make_shared<Frame>()));
    EXPECT_TRUE(host.access.enqueue(0, std::make_shared<Frame>()));
    EXPECT_FALSE(host.access.enqueue(0, std::make_shared<Frame>()));
    EXPECT_EQ(host.access.queued(0), 2U);
}

}  // namespace
}  // namespace sbsim::radio
