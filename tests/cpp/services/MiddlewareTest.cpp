// Services on a real SUMO run (the generated 4x4 grid: one departure a second, 120 s): created on
// departure, triggered on their own clocks, finished on arrival or at the end, their timers gone
// with their vehicle; filters on SUMO's vehicle types; storyboard signals at activation; beacons
// through the medium to exactly the vehicles in range, late ones to vehicles that left dropped.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "ServicesTestSupport.h"
#include "SumoTestSupport.h"
#include "TestPrinters.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/radio/disc/DiscMedium.h"
#include "sbsim/services/ServiceManager.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/storyboard/BoardFeed.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/CarSetCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/effects/SignalEffect.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::services::test {
namespace {

using traffic::SumoBridge;

class SumoRun;

/// Departures and arrivals as the bridge announces them, heard after the service manager.
struct VehicleWatch : kernel::Listener {
    SumoRun* run = nullptr;
    std::map<std::string, SimTime> departed;
    std::map<std::string, SimTime> arrived;
    std::vector<std::string> departureOrder;
    std::map<std::string, std::string> typeAtDeparture;
    std::set<std::string> withMiddlewareAtDeparture;
    std::set<std::string> withMiddlewareAfterArrival;
    void receiveSignal(kernel::Module& source, kernel::SignalId id, std::string_view value) override;
};

/// SUMO bridge, service manager and medium wired as app/run/Scenario.cpp wires them, on the small scenario.
class SumoRun {
public:
    explicit SumoRun(std::string_view servicesXml, radio::DiscSettings disc = {}, std::optional<SimTime> end = {})
        : sumo(sim.emplaceModule<SumoBridge>(settings(end))),
          manager(sim.emplaceModule<ServiceManager>(ServicesConfig::parse(servicesXml, "test.xml"), secs(0.1),
                                                    sumo.snapshot(), registry)),
          medium(sim.emplaceModule<radio::DiscMedium>(
              disc, sumo.snapshot(), [this](const std::string& id) { return manager.middlewareOf(id); })) {
        manager.setMedium(medium);
        manager.attach(sumo);
        registry.attach(sumo);
        sumo.demandColumns(ServiceManager::columns());
        watch.run = this;
        sumo.subscribe(SumoBridge::departedSignal, watch);
        sumo.subscribe(SumoBridge::arrivedSignal, watch);
    }

    /// Runs to the end, notes the state there, then Simulation::finish().
    void run() {
        sim.run();
        endTime = sim.now();
        eventsLeft = sim.futureEvents().size();
        runningAtEnd = static_cast<std::size_t>(sumo.snapshot().size());
        modulesAtEnd = sim.moduleCount();
        log.simulationFinishing = true;
        sim.finish();
    }

    /// When `vehicle` stopped receiving: its arrival, or after the end.
    std::optional<SimTime> arrival(const std::string& vehicle) const {
        const auto it = watch.arrived.find(vehicle);
        return it == watch.arrived.end() ? std::nullopt : std::optional(it->second);
    }

    ProbeLog log;
    VehicleWatch watch;
    traffic::VehicleRegistry registry;
    kernel::Simulation sim;
    SumoBridge& sumo;
    ServiceManager& manager;
    radio::DiscMedium& medium;
    SimTime endTime;
    std::size_t eventsLeft = 0;
    std::size_t runningAtEnd = 0;
    std::size_t modulesAtEnd = 0;

private:
    static traffic::SumoSettings settings(std::optional<SimTime> end) {
        traffic::SumoSettings s = sbsim::test::scenarioSettings();
        s.end = end;
        return s;
    }
};

void VehicleWatch::receiveSignal(kernel::Module&, kernel::SignalId id, std::string_view value) {
    const std::string v(value);
    if (id == SumoBridge::departedSignal) {
        departed[v] = run->sim.now();
        departureOrder.push_back(v);
        const auto& snap = run->sumo.snapshot();
        if (const auto i = snap.indexOf(v)) typeAtDeparture[v] = snap.typeId(*i);
        if (run->manager.middlewareOf(v) != nullptr) withMiddlewareAtDeparture.insert(v);
    } else if (id == SumoBridge::arrivedSignal) {
        arrived[v] = run->sim.now();
        if (run->manager.middlewareOf(v) != nullptr) withMiddlewareAfterArrival.insert(v);
    }
}

/// t0 + k * step for k = 1.. while before `stop` (or up to and including `last` without one).
std::vector<SimTime> gridTimes(SimTime t0, SimTime step, std::optional<SimTime> stop, SimTime last) {
    std::vector<SimTime> out;
    for (SimTime t = t0 + step; stop ? t < *stop : t <= last; t += step) out.push_back(t);
    return out;
}

/// A station's trigger times on its own clock: departed + phase + k * step while before `stop` (its
/// arrival) or up to `last`.
std::vector<SimTime> clockTimes(SimTime departed, SimTime phase, SimTime step, std::optional<SimTime> stop,
                                SimTime last) {
    std::vector<SimTime> out;
    for (SimTime t = departed + phase; stop ? t < *stop : t <= last; t += step) out.push_back(t);
    return out;
}

TEST(MiddlewareSumo, ServicesLiveFromDepartureToArrival) {
    SumoRun s(R"(<services><service type="TestProbe" tick="0.25" farTimer="1000" askSumo="1"/></services>)");
    s.run();

    ASSERT_EQ(s.endTime, secs(120));
    ASSERT_GT(s.watch.arrived.size(), 10u);
    ASSERT_GT(s.runningAtEnd, 10u);
    EXPECT_EQ(s.watch.departed.size(), s.sumo.vehiclesSeen());
    EXPECT_EQ(s.log.records.size(), s.watch.departed.size()) << "one probe per vehicle";
    EXPECT_EQ(s.manager.servicesCreated(), s.watch.departed.size());
    EXPECT_EQ(s.watch.withMiddlewareAtDeparture.size(), s.watch.departed.size());
    EXPECT_TRUE(s.watch.withMiddlewareAfterArrival.empty());

    std::set<std::string> seen;
    for (const auto& r : s.log.records) {
        SCOPED_TRACE(r->name);
        const std::string& v = r->vehicle;
        ASSERT_TRUE(s.watch.departed.count(v)) << "a probe for a vehicle that never departed";
        EXPECT_TRUE(seen.insert(v).second) << "two probes on one vehicle";
        const SimTime departed = s.watch.departed.at(v);
        const std::optional<SimTime> arrived = s.arrival(v);
        // Created on departure and hosted before initialize().
        EXPECT_EQ(r->initializeCalls, 1);
        EXPECT_EQ(r->initializedAt, departed);
        EXPECT_EQ(r->name, v + ".TestProbe");
        EXPECT_EQ(r->controllerId, v);
        EXPECT_TRUE(r->selfIndexAtInit.has_value());
        EXPECT_EQ(r->liveType, s.watch.typeAtDeparture.at(v)) << "vehicle() asks SUMO already in initialize()";
        // 10 triggers a second on the station's own clock; none at or after the arrival step.
        const SimTime phase = Middleware::clockPhase(s.sim.seed(), v, secs(0.1));
        EXPECT_EQ(r->triggers, clockTimes(departed, phase, secs(0.1), arrived, s.endTime));
        EXPECT_EQ(r->ticks, gridTimes(departed, secs(0.25), arrived, s.endTime)) << "the service's own timer";
        EXPECT_EQ(r->farFired, 0);
        EXPECT_EQ(r->callsAfterFinish, 0);
        ASSERT_EQ(r->finishes.size(), 1u);
        if (arrived) {
            EXPECT_EQ(r->finishes[0], *arrived);
            EXPECT_FALSE(r->finishedBySimulationFinish);
            EXPECT_EQ(r->live, nullptr);
            EXPECT_FALSE(r->farTimer->isScheduled()) << "its timers went with the vehicle";
        } else {
            EXPECT_EQ(r->finishes[0], s.endTime);
            EXPECT_TRUE(r->finishedBySimulationFinish);
            ASSERT_NE(r->live, nullptr);
            EXPECT_TRUE(r->farTimer->isScheduled());
            EXPECT_EQ(r->farTimer->arrivalModule(), static_cast<kernel::Module*>(r->live));
        }
    }
    // What the kernel holds at the end: per running vehicle its middleware's trigger and the probe's
    // tick and far timer; nothing for vehicles that left.
    EXPECT_EQ(s.eventsLeft, 3 * s.runningAtEnd);
    EXPECT_EQ(s.modulesAtEnd, 3 + 2 * s.runningAtEnd);
}

TEST(MiddlewareSumo, StationsTriggerOnTheirOwnClocks) {
    // One shared tick made 99.9 % of CAMs start within 5 ms of each other and collide; Artery gives
    // each middleware its own phase. Here the triggers of different vehicles rarely share an instant.
    SumoRun s(R"(<services><service type="TestProbe"/></services>)", {}, secs(30));
    s.run();
    std::map<SimTime, std::vector<std::string>> byTime;
    for (const auto& [t, v] : s.log.triggerOrder) byTime[t].push_back(v);
    ASSERT_GT(s.log.triggerOrder.size(), 2000u);
    std::size_t shared = 0;
    for (const auto& [t, vehicles] : byTime) shared += vehicles.size() > 1 ? vehicles.size() : 0;
    EXPECT_LT(static_cast<double>(shared) / static_cast<double>(s.log.triggerOrder.size()), 0.01);
    // Each vehicle keeps its own offset within the 100 ms period, and no two share one.
    std::map<std::string, std::set<SimTime::rep>> offsets;
    for (const auto& [t, v] : s.log.triggerOrder) offsets[v].insert(t.raw() % 100'000'000);
    std::set<SimTime::rep> distinct;
    for (const auto& [v, o] : offsets) {
        EXPECT_EQ(o.size(), 1u) << v << ": one clock, one offset";
        distinct.insert(o.begin(), o.end());
    }
    EXPECT_EQ(distinct.size(), offsets.size());
}

TEST(MiddlewareSumo, FiltersUseTheSumoVehicleType) {
    SumoRun s(R"(<services>
        <service type="TestProbe"><filters><type pattern="truck"/></filters></service>
        <service type="TestProbeB"><filters><name pattern="veh\d*[05]" match="inverse"/></filters></service>
    </services>)",
              {}, secs(40));
    s.run();
    const std::regex fiveOrTen(R"(veh\d*[05])");
    std::size_t trucks = 0, none = 0;
    for (const auto& [v, t] : s.watch.departed) {
        SCOPED_TRACE(v);
        const bool truck = s.watch.typeAtDeparture.at(v) == "truck";
        const bool named = std::regex_match(v, fiveOrTen);
        trucks += truck;
        none += !truck && named;
        EXPECT_EQ(s.log.find(v, "TestProbe") != nullptr, truck);
        EXPECT_EQ(s.log.find(v, "TestProbeB") != nullptr, !named);
        EXPECT_EQ(s.watch.withMiddlewareAtDeparture.count(v) != 0, truck || !named);
    }
    EXPECT_GT(trucks, 0u);
    EXPECT_LT(trucks, s.watch.departed.size());
    EXPECT_GT(none, 0u) << "some vehicles run no service at all";
}

TEST(MiddlewareSumo, StoryboardSignalsReachTheEgoAtActivation) {
    SumoRun s(R"(<services>
        <service type="TestProbe"/>
        <service type="TestProbeB" listenAll="1"><filters><name pattern="veh2"/></filters></service>
    </services>)",
              {}, secs(25));
    auto& board = s.sim.emplaceModule<storyboard::Storyboard>(s.registry);
    const storyboard::BoardFeed feed(s.sumo, s.sumo.snapshot(), board);
    board.registerStory(signalStory("brake", "veh5", 20, "go"));
    board.registerStory(signalStory("hello", "veh3", 0, "hi"));  // true from veh3's first step on
    s.run();

    ASSERT_TRUE(s.watch.departed.count("veh2") && s.watch.departed.count("veh3") && s.watch.departed.count("veh5"));
    ASSERT_FALSE(s.arrival("veh2") || s.arrival("veh5")) << "the test needs veh2 and veh5 running at 20 s";
    ASSERT_LT(s.watch.departed.at("veh2"), s.watch.departed.at("veh3"));
    const std::string hello = s.watch.departed.at("veh3").str() + " hello veh3 hi";
    using V = std::vector<std::string>;
    EXPECT_EQ(signalsOf(s.log.find("veh5")), (V{"20 brake veh5 go"}));
    EXPECT_EQ(signalsOf(s.log.find("veh3")), (V{hello})) << "at the step the vehicle departed in";
    EXPECT_EQ(signalsOf(s.log.find("veh2", "TestProbeB")), (V{hello, "20 brake veh5 go"}));
    for (const auto& r : s.log.records) {
        if (r->vehicle == "veh3" || r->vehicle == "veh5" || r->type == "TestProbeB") continue;
        EXPECT_TRUE(r->signals.empty()) << r->name;
    }
}

/// Beacons on every trigger through a medium of `range` and `latency`; checks that each beacon
/// reached exactly the vehicles within range at sending that were still there at delivery time,
/// each exactly `latency` after it was sent. Returns how many (beacon, receiver) pairs in range
/// were dropped because the receiver had left.
std::size_t checkBeacons(SimTime latency, SimTime end, double range) {
    radio::DiscSettings disc;
    disc.range = range;
    disc.latency = latency;
    SumoRun s(R"(<services><service type="TestProbe" beacon="1"/></services>)", disc, end);
    s.log.beaconRange = range;
    s.run();

    // (sender, seq) -> receivers, as delivered.
    std::map<std::pair<std::string, int>, std::set<std::string>> delivered;
    std::size_t indications = 0;
    for (const auto& r : s.log.records) {
        for (const Indication& i : r->indications) {
            ++indications;
            EXPECT_EQ(i.at, i.sentAt + latency) << r->vehicle << " from " << i.sender;
            EXPECT_NE(i.sender, r->vehicle);
            EXPECT_TRUE((delivered[{i.sender, i.seq}].insert(r->vehicle).second)) << "delivered twice";
        }
    }
    std::size_t sent = 0, expectedTotal = 0, dropped = 0, mismatches = 0;
    for (const auto& r : s.log.records) {
        for (const Sent& b : r->sent) {
            ++sent;
            const SimTime due = b.at + latency;
            std::set<std::string> expected;
            for (const std::string& v : b.inRange) {
                const auto left = s.arrival(v);
                if (due > s.endTime) continue;  // the run ended first
                if (left && *left <= due) {
                    ++dropped;  // left before (or at the step of) the delivery time
                } else {
                    expected.insert(v);
                }
            }
            expectedTotal += expected.size();
            const auto it = delivered.find({r->vehicle, b.seq});
            const std::set<std::string> got = it == delivered.end() ? std::set<std::string>{} : it->second;
            if (got != expected && mismatches++ < 5) {
                ADD_FAILURE() << r->vehicle << " beacon " << b.seq << " sent at " << b.at.str() << ": " << got.size()
                              << " receivers, expected " << expected.size();
            }
        }
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_GT(sent, 1000u);
    EXPECT_GT(expectedTotal, 1000u);
    EXPECT_EQ(indications, expectedTotal);
    const radio::Medium::Counts counts = s.medium.counts().at("Beacon");
    EXPECT_EQ(counts.sent, sent);
    EXPECT_EQ(counts.delivered, indications);
    return dropped;
}

TEST(MiddlewareSumo, BeaconsReachExactlyTheVehiclesInRangeSubMillisecondLatency) {
    EXPECT_EQ(checkBeacons(SimTime::fromNanoseconds(300'000), secs(40), 150), 0u);
}

TEST(MiddlewareSumo, BeaconsToVehiclesThatLeftBeforeDeliveryAreDropped) {
    EXPECT_GT(checkBeacons(SimTime::fromMilliseconds(1500), secs(120), 150), 0u)
        << "the scenario should have vehicles leaving while beacons to them are in the air";
}

}  // namespace
}  // namespace sbsim::services::test
