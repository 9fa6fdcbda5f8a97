// Stationary stations (roadside units) beside the snapshot's vehicles, in both media: a unit's
// frame reaches the vehicles and units in range and no others, vehicles' frames reach units, and
// units are visited after the vehicles, in the order they were added.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/FixedStations.h"
#include "sbsim/radio/Receiver.h"
#include "sbsim/radio/channel/ChannelMedium.h"
#include "sbsim/radio/disc/DiscMedium.h"

namespace sbsim::radio {
namespace {

using kernel::SimTime;

struct Ping : V2xMessage {
    std::string_view typeName() const override { return "Ping"; }
    std::size_t byteSize() const override { return 100; }
};

struct Station : kernel::Module, Receiver {
    explicit Station(std::string id) : kernel::Module(std::move(id)) {}
    void receive(const V2xMessage& message) override { received.push_back(message.sender()); }
    std::vector<std::string> received;
};

struct Sender : kernel::Module {
    Sender() : kernel::Module("sender") {}
    struct Action : kernel::Message {
        explicit Action(std::function<void()> fn) : kernel::Message("send"), f(std::move(fn)) {}
        std::function<void()> f;
    };
    void at(SimTime t, std::function<void()> f) {
        actions.push_back(std::make_unique<Action>(std::move(f)));
        times.push_back(t);
    }
    void initialize() override {
        for (std::size_t k = 0; k < actions.size(); ++k) scheduleAt(times[k], *actions[k]);
    }
    void handleMessage(kernel::Message& msg) override { static_cast<Action&>(msg).f(); }
    std::vector<std::unique_ptr<Action>> actions;
    std::vector<SimTime> times;
};

struct Order : MessageTrace {
    void record(const TraceLine& l, SimTime) override {
        if (l.event == TraceLine::Event::Rx) rx.push_back(std::string(l.sender) + ">" + std::string(l.station));
        if (l.event == TraceLine::Event::Tx) tx.emplace_back(l.x, l.y);
    }
    std::vector<std::string> rx;
    std::vector<std::pair<double, double>> tx;
};

/// Vehicles on the x axis and units anywhere; `channel`: the 802.11p model, else the disc.
struct Scene {
    Scene(bool channel, const std::vector<std::pair<std::string, double>>& vehicles,
          const std::vector<std::pair<std::string, Eigen::Vector2d>>& units, double discRange = 500) {
        std::vector<traffic::VehicleSnapshot::Vehicle> vs;
        for (const auto& [id, x] : vehicles) {
            traffic::VehicleSnapshot::Vehicle v;
            v.id = id;
            v.x = x;
            vs.push_back(v);
            stations[id] = &sim.emplaceModule<Station>(id);
        }
        for (const auto& [id, at] : units) stations[id] = &sim.emplaceModule<Station>(id);
        snapshot.assign(std::move(vs), SimTime::zero());
        const auto directory = [this](const std::string& id) -> kernel::Module* {
            const auto it = stations.find(id);
            return it == stations.end() ? nullptr : it->second;
        };
        if (channel) {
            ChannelSettings s;
            s.shadowingSigmaDb = 0;  // outcomes follow distance alone
            medium = &sim.emplaceModule<ChannelMedium>(s, snapshot, directory);
        } else {
            DiscSettings s;
            s.range = discRange;
            medium = &sim.emplaceModule<DiscMedium>(s, snapshot, directory);
        }
        for (const auto& [id, at] : units) medium->addFixedStation(id, at);
        medium->setTrace(&order);
        sender = &sim.emplaceModule<Sender>();
    }
    void send(double t, const std::string& from) {
        sender->at(SimTime::fromSeconds(t), [this, from] { medium->broadcast(from, std::make_unique<Ping>()); });
    }
    std::vector<std::string> heard(const std::string& id) const { return stations.at(id)->received; }

    kernel::Simulation sim{7};
    traffic::VehicleSnapshot snapshot;
    std::map<std::string, Station*> stations;
    Medium* medium = nullptr;
    Sender* sender = nullptr;
    Order order;
};

using Names = std::vector<std::string>;

TEST(FixedStations, DiscUnitsSendAndReceiveWithinRangeOnly) {
    Scene s(false, {{"a", 0}, {"b", 400}, {"c", 700}}, {{"rsu", {100, 0}}, {"rsu2", {1500, 0}}, {"rsu3", {1000, 0}}});
    s.send(0.1, "rsu");   // a 100 m, b 300 m; c 600 m, rsu3 900 m, rsu2 1400 m: no
    s.send(0.2, "b");     // a, c, rsu (300 m); rsu3 600 m: no
    s.send(0.3, "rsu3");  // c 300 m, rsu2 500 m (inclusive); b 600 m: no
    s.sim.run(SimTime::fromSeconds(1));
    EXPECT_EQ(s.heard("a"), (Names{"rsu", "b"}));
    EXPECT_EQ(s.heard("b"), (Names{"rsu"}));
    EXPECT_EQ(s.heard("c"), (Names{"b", "rsu3"}));
    EXPECT_EQ(s.heard("rsu"), (Names{"b"}));
    EXPECT_EQ(s.heard("rsu2"), (Names{"rsu3"}));
    EXPECT_TRUE(s.heard("rsu3").empty());
    // Vehicles first (ascending), then the units in the order they were added; a unit's frame
    // starts at its own position.
    EXPECT_EQ(s.order.rx, (Names{"rsu>a", "rsu>b", "b>a", "b>c", "b>rsu", "rsu3>c", "rsu3>rsu2"}));
    EXPECT_EQ(s.order.tx.front(), (std::pair<double, double>{100, 0}));
    EXPECT_EQ(s.medium->counts().at("Ping").sent, 3u);
    EXPECT_EQ(s.medium->counts().at("Ping").delivered, 7u);
}

TEST(FixedStations, ChannelUnitsSendAndReceiveWithinRangeOnly) {
    // With the defaults a frame is received to about 290 m and nothing beyond the ~910 m cutoff.
    Scene s(true, {{"a", 0}, {"b", 100}, {"far", 3000}}, {{"rsu", {50, 30}}, {"rsu2", {3100, 0}}});
    s.send(0.1, "rsu");
    s.send(0.2, "a");
    s.send(0.3, "rsu2");
    s.sim.run(SimTime::fromSeconds(1));
    EXPECT_EQ(s.heard("a"), (Names{"rsu"}));
    EXPECT_EQ(s.heard("b"), (Names{"rsu", "a"}));
    EXPECT_EQ(s.heard("far"), (Names{"rsu2"}));
    EXPECT_EQ(s.heard("rsu"), (Names{"a"}));
    EXPECT_TRUE(s.heard("rsu2").empty());
    EXPECT_EQ(s.order.tx.front(), (std::pair<double, double>{50, 30}));
    auto* channel = dynamic_cast<ChannelMedium*>(s.medium);
    ASSERT_NE(channel, nullptr);
    EXPECT_EQ(channel->transmissions(), 3u);
    EXPECT_EQ(channel->receptions(), 5u);
    EXPECT_TRUE(channel->channelBusyRatio("rsu").has_value());
}

TEST(FixedStations, RejectsADuplicateIdOrAPositionThatIsNotFinite) {
    FixedStations f;
    f.add("rsu", {1, 2});
    EXPECT_THROW(f.add("rsu", {3, 4}), std::invalid_argument);
    EXPECT_THROW(f.add("x", {std::nan(""), 0}), std::invalid_argument);
    EXPECT_THROW(f.add("", {0, 0}), std::invalid_argument);
    EXPECT_EQ(f.size(), 1);
    EXPECT_EQ(f.indexOf("rsu"), 0);
    EXPECT_FALSE(f.indexOf("x").has_value());
}

}  // namespace
}  // namespace sbsim::radio
