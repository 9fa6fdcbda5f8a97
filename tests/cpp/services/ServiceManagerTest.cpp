// The service manager and the middleware on hand-made steps (no SUMO): which vehicles get which
// services, the service lifecycle (hosting, initialize, triggers on each station's own clock, finish,
// own timers), and storyboard signals routed to the ego vehicle's services and to listeners.

#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "ServicesTestSupport.h"
#include "TestPrinters.h"
#include "sbsim/services/Middleware.h"
#include "sbsim/services/ServiceManager.h"
#include "sbsim/services/ServicesConfig.h"
#include "sbsim/storyboard/BoardFeed.h"
#include "sbsim/storyboard/Storyboard.h"
#include "sbsim/storyboard/conditions/AndCondition.h"
#include "sbsim/storyboard/conditions/CarSetCondition.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"
#include "sbsim/storyboard/effects/SignalEffect.h"

namespace sbsim::services::test {
namespace {

/// Station `id`'s trigger times on its own clock, having departed at `departed`: departed + phase +
/// k * step for k = 0.. while <= last.
std::vector<SimTime> clock(const kernel::Simulation& sim, const std::string& id, SimTime departed, SimTime step,
                           SimTime last) {
    std::vector<SimTime> out;
    for (SimTime t = departed + Middleware::clockPhase(sim.seed(), id, step); t <= last; t += step) out.push_back(t);
    return out;
}

/// The service types hosted on `vehicle`, in hosting order (from the middleware's own list).
std::vector<std::string> hostedTypes(const ServiceManager& manager, const std::string& vehicle) {
    std::vector<std::string> out;
    const Middleware* m = manager.middlewareOf(vehicle);
    if (m == nullptr) return out;
    for (const Service* s : m->services()) out.push_back(s->name().substr(vehicle.size() + 1));
    return out;
}

using Types = std::vector<std::string>;

// --- filters ---------------------------------------------------------------------------------

TEST(ServiceManagerFilters, NamePatternsTypePatternsInverseAndOperators) {
    Harness h(R"(<services>
        <service type="TestProbe"/>
        <service type="TestProbeB"><filters><type pattern="truck"/></filters></service>
        <service type="TestProbeC"><filters><name pattern="police\d+"/></filters></service>
        <service type="TestProbeD"><filters><name pattern="police\d+" match="inverse"/></filters></service>
        <service type="TestProbeE"><filters operator="and"><name pattern="police\d+"/><type pattern="truck"/></filters></service>
        <service type="TestProbeF"><filters><name pattern="police\d+"/><type pattern="truck"/></filters></service>
    </services>)");
    h.step(secs(1), {vehicle("police1", 0, 0, "car"), vehicle("police2", 10, 0, "truck"),
                     vehicle("veh1", 20, 0, "truck"), vehicle("veh2", 30, 0, "car"), vehicle("police", 40, 0, "car"),
                     vehicle("xpolice3", 50, 0, "car"), vehicle("veh3", 60, 0, "truck2")});
    std::map<std::string, Types> hosted;
    h.at(secs(1), [&] {
        for (const std::string& id : h.snapshot.ids()) hosted[id] = hostedTypes(h.manager, id);
    });
    h.sim.run(secs(1));

    // Patterns must match the whole id or type; without operator, any passing filter is enough.
    const std::map<std::string, Types> expected = {
        {"police1", {"TestProbe", "TestProbeC", "TestProbeF"}},
        {"police2", {"TestProbe", "TestProbeB", "TestProbeC", "TestProbeE", "TestProbeF"}},
        {"veh1", {"TestProbe", "TestProbeB", "TestProbeD", "TestProbeF"}},
        {"veh2", {"TestProbe", "TestProbeD"}},
        {"police", {"TestProbe", "TestProbeD"}},
        {"xpolice3", {"TestProbe", "TestProbeD"}},
        {"veh3", {"TestProbe", "TestProbeD"}},
    };
    EXPECT_EQ(hosted, expected);
    EXPECT_EQ(h.manager.servicesCreated(), 20u);
    ASSERT_EQ(h.log.records.size(), 20u);
    // The probes saw the same thing from the inside.
    std::map<std::string, Types> seen;
    for (const auto& r : h.log.records) {
        EXPECT_EQ(r->initializeCalls, 1) << r->name;
        seen[r->vehicle].push_back(r->type);
    }
    EXPECT_EQ(seen, expected);
}

TEST(ServiceManagerFilters, VehicleWithoutMatchingServiceGetsNoMiddleware) {
    Harness h(R"(<services><service type="TestProbe"><filters><type pattern="truck"/></filters></service></services>)");
    const std::size_t modulesBefore = h.sim.moduleCount();
    h.step(secs(1), {vehicle("car1"), vehicle("truck1", 5, 0, "truck")});
    std::size_t modulesAt1 = 0;
    h.at(secs(1), [&] { modulesAt1 = h.sim.moduleCount(); });
    h.step(secs(2), {});  // both arrive
    h.sim.run(secs(3));
    EXPECT_EQ(modulesAt1, modulesBefore + 2) << "one middleware and one service, for the truck only";
    EXPECT_EQ(h.manager.servicesCreated(), 1u);
    ASSERT_EQ(h.log.records.size(), 1u);
    EXPECT_EQ(h.log.records[0]->vehicle, "truck1");
    EXPECT_EQ(h.manager.middlewareOf("car1"), nullptr);
    EXPECT_EQ(h.sim.moduleCount(), modulesBefore) << "the truck's modules are gone after it arrived";
}

TEST(ServiceManager, RejectsUnknownServiceTypesAndBadIntervals) {
    VehicleSnapshot snapshot;
    traffic::VehicleRegistry registry;
    const auto config = [] {
        return ServicesConfig::parse(R"(<services><service type="NoSuchService"/></services>)", "x.xml");
    };
    EXPECT_THROW(ServiceManager(config(), secs(0.1), snapshot, registry), std::out_of_range);
    const auto ok = [] {
        return ServicesConfig::parse(R"(<services><service type="TestProbe"/></services>)", "x.xml");
    };
    EXPECT_THROW(ServiceManager(ok(), SimTime::zero(), snapshot, registry), std::invalid_argument);
    EXPECT_THROW(ServiceManager(ok(), secs(-0.1), snapshot, registry), std::invalid_argument);
    EXPECT_NO_THROW(ServiceManager(ok(), secs(0.1), snapshot, registry));
}

// --- lifecycle -------------------------------------------------------------------------------

TEST(ServiceLifecycle, HostedBeforeInitializeTriggeredOnItsClockFinishedOnArrival) {
    Harness h(R"(<services><service type="TestProbe"/></services>)");
    const std::size_t modulesBefore = h.sim.moduleCount();
    h.step(secs(1), {vehicle("a")});
    h.step(secs(2), {vehicle("a"), vehicle("b", 10)});
    h.step(secs(2.35), {vehicle("a"), vehicle("b", 10), vehicle("c", 20)});  // off the 0.1 s grid
    h.step(secs(3.5), {vehicle("b", 10), vehicle("c", 20)});                 // a arrives
    std::optional<Middleware*> aAfterArrival;
    h.at(secs(3.5), [&] { aAfterArrival = h.manager.middlewareOf("a"); });
    h.sim.run(secs(5));
    h.log.simulationFinishing = true;
    h.sim.finish();

    const ProbeRecord* a = h.log.find("a");
    const ProbeRecord* b = h.log.find("b");
    const ProbeRecord* c = h.log.find("c");
    ASSERT_TRUE(a && b && c);
    // Hosted before initialize(): vehicleId(), vehicle() and selfIndex() already work there.
    EXPECT_EQ(a->name, "a.TestProbe");
    EXPECT_EQ(a->controllerId, "a");
    EXPECT_EQ(a->selfIndexAtInit, std::optional<VehicleSnapshot::Index>(0));
    EXPECT_EQ(c->selfIndexAtInit, std::optional<VehicleSnapshot::Index>(2));
    EXPECT_EQ(a->initializedAt, secs(1));
    EXPECT_EQ(b->initializedAt, secs(2));
    EXPECT_EQ(c->initializedAt, secs(2.35));

    // Every 0.1 s on each station's own clock, the first within 0.1 s of the departure, off any
    // grid; a's triggers end before its arrival (3.5): at that instant the step comes first.
    EXPECT_EQ(a->triggers, clock(h.sim, "a", secs(1), secs(0.1), secs(3.5) - SimTime::fromNanoseconds(1)));
    EXPECT_EQ(a->triggers.size(), 25u);
    EXPECT_EQ(b->triggers, clock(h.sim, "b", secs(2), secs(0.1), secs(5)));
    EXPECT_EQ(c->triggers, clock(h.sim, "c", secs(2.35), secs(0.1), secs(5)));
    EXPECT_GT(c->triggers.front(), secs(2.35)) << "never in the instant of the departure";
    EXPECT_LE(c->triggers.front(), secs(2.45));

    EXPECT_EQ(a->finishes, std::vector<SimTime>{secs(3.5)});
    EXPECT_FALSE(a->finishedBySimulationFinish);
    EXPECT_EQ(a->live, nullptr) << "a's service is destroyed once it finished";
    EXPECT_EQ(aAfterArrival, std::optional<Middleware*>(nullptr)) << "the manager forgets a's middleware";
    // Finished at the end: the time of the run's last event, a trigger shortly before 5 s.
    EXPECT_LE(h.sim.now(), secs(5));
    EXPECT_EQ(b->finishes, std::vector<SimTime>{h.sim.now()});
    EXPECT_TRUE(b->finishedBySimulationFinish);
    EXPECT_EQ(c->finishes, std::vector<SimTime>{h.sim.now()});
    for (const ProbeRecord* r : {a, b, c}) EXPECT_EQ(r->callsAfterFinish, 0) << r->name;
    EXPECT_EQ(h.sim.moduleCount(), modulesBefore + 4) << "b and c: a middleware and a service each";
    EXPECT_EQ(h.manager.servicesCreated(), 3u);
}

TEST(ServiceLifecycle, EachStationTriggersOnItsOwnClockOfAnyInterval) {
    Harness h(R"(<services><service type="TestProbe"/></services>)", {}, secs(0.25));
    h.step(secs(1), {vehicle("a")});
    h.step(secs(1.3), {vehicle("a"), vehicle("b")});
    h.step(secs(1.5), {vehicle("a"), vehicle("b"), vehicle("c")});
    h.sim.run(secs(3));
    EXPECT_EQ(h.log.find("a")->triggers, clock(h.sim, "a", secs(1), secs(0.25), secs(3)));
    EXPECT_EQ(h.log.find("b")->triggers, clock(h.sim, "b", secs(1.3), secs(0.25), secs(3)));
    EXPECT_EQ(h.log.find("c")->triggers, clock(h.sim, "c", secs(1.5), secs(0.25), secs(3)));
}

TEST(MiddlewareClock, PhasesAreUniformInTheIntervalAndKeyedBySeedAndStation) {
    const SimTime interval = secs(0.1);
    constexpr int kStations = 20000;
    std::vector<int> tenths(10, 0);
    int differentSeed = 0;
    for (int i = 0; i < kStations; ++i) {
        const std::string id = "veh" + std::to_string(i);
        const SimTime phase = Middleware::clockPhase(7, id, interval);
        ASSERT_GT(phase, SimTime::zero());
        ASSERT_LE(phase, interval);
        EXPECT_EQ(phase, Middleware::clockPhase(7, id, interval)) << "a pure function of (seed, station)";
        differentSeed += phase != Middleware::clockPhase(8, id, interval);
        ++tenths[static_cast<std::size_t>(std::min<SimTime::rep>((phase.raw() - 1) * 10 / interval.raw(), 9))];
    }
    // Uniform: each tenth of the interval holds 2,000 +- 5 standard deviations (~42).
    for (const int n : tenths) EXPECT_NEAR(n, kStations / 10, 220);
    EXPECT_GT(differentSeed, kStations * 99 / 100) << "another seed, other phases";
    // The phase scales with the interval: the same draw, a fraction of it.
    const double at01 = Middleware::clockPhase(7, "veh1", secs(0.1)).seconds() / 0.1;
    const double at1 = Middleware::clockPhase(7, "veh1", secs(1)).seconds() / 1.0;
    EXPECT_NEAR(at01, at1, 1e-7);
}

TEST(ServiceLifecycle, ServicesRunInFileOrderOnEachVehicle) {
    Harness h(
        R"(<services><service type="TestProbeC"/><service type="TestProbe"/><service type="TestProbeB"/></services>)");
    h.step(secs(1), {vehicle("a")});
    h.sim.run(secs(1.1));
    EXPECT_EQ(hostedTypes(h.manager, "a"), (Types{"TestProbeC", "TestProbe", "TestProbeB"}));
    ASSERT_EQ(h.log.records.size(), 3u);
    EXPECT_EQ(h.log.records[0]->type, "TestProbeC") << "created (and initialized) in file order";
    EXPECT_EQ(h.log.records[2]->type, "TestProbeB");
}

TEST(ServiceLifecycle, OwnTimersDieWithTheVehicle) {
    Harness h(R"(<services><service type="TestProbe" tick="0.3" farTimer="50"/></services>)");
    h.step(secs(1), {vehicle("a"), vehicle("b")});
    h.step(secs(2.05), {vehicle("b")});  // a arrives
    bool aFarScheduledAfterArrival = true;
    h.at(secs(2.05), [&] { aFarScheduledAfterArrival = h.log.find("a")->farTimer->isScheduled(); });
    h.sim.run(secs(10));

    const ProbeRecord* a = h.log.find("a");
    const ProbeRecord* b = h.log.find("b");
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->ticks, (std::vector<SimTime>{secs(1.3), secs(1.6), secs(1.9)}));
    EXPECT_EQ(b->ticks.size(), 30u) << "b's timer keeps running until 10 s";
    EXPECT_FALSE(aFarScheduledAfterArrival) << "a timer the service scheduled is cancelled when its vehicle arrives";
    EXPECT_FALSE(a->farTimer->isScheduled());
    EXPECT_EQ(a->callsAfterFinish, 0);
    EXPECT_EQ(a->farFired, 0);
    ASSERT_TRUE(b->farTimer->isScheduled());
    EXPECT_EQ(b->farTimer->arrivalTime(), secs(50));
    EXPECT_EQ(b->farTimer->arrivalModule(), static_cast<kernel::Module*>(b->live));
    // Left in the kernel: b's middleware trigger, b's tick and b's far timer; nothing for a.
    EXPECT_EQ(h.sim.futureEvents().size(), 3u);

    h.sim.run(secs(60));
    EXPECT_EQ(b->farFired, 1) << "the far timer does work while its vehicle is running";
    EXPECT_EQ(a->farFired, 0);
}

// --- storyboard signals ----------------------------------------------------------------------

TEST(ServiceSignals, EgoServicesGetTheSignalListenersGetAllOnce) {
    Harness h(R"(<services>
        <service type="TestProbe"><filters><name pattern="d" match="inverse"/></filters></service>
        <service type="TestProbeB" listenAll="1"><filters><name pattern="a|b"/></filters></service>
    </services>)");
    auto& board = h.sim.emplaceModule<storyboard::Storyboard>(h.registry);
    const storyboard::BoardFeed feed(h.sumo, h.snapshot, board);
    board.registerStory(signalStory("toB", "b", 3, "hello"));
    board.registerStory(signalStory("toD", "d", 4, "nobody"));  // d has no services
    board.registerStory(signalStory("toC", "c", 5, "for c"));
    board.registerStory(signalStory("toC2", "c", 7, "again"));
    const std::vector<VehicleSnapshot::Vehicle> all = {vehicle("a"), vehicle("b", 5), vehicle("c", 10),
                                                       vehicle("d", 15)};
    for (int t = 1; t <= 5; ++t) h.step(secs(t), all);
    h.step(secs(6), {vehicle("b", 5), vehicle("c", 10), vehicle("d", 15)});  // a (a listener) arrives
    h.step(secs(7), {vehicle("b", 5), vehicle("c", 10), vehicle("d", 15)});
    h.step(secs(8), {vehicle("b", 5), vehicle("c", 10), vehicle("d", 15)});
    h.sim.run(secs(9));

    using V = std::vector<std::string>;
    EXPECT_EQ(signalsOf(h.log.find("b", "TestProbe")), (V{"3 toB b hello"}));
    EXPECT_EQ(signalsOf(h.log.find("b", "TestProbeB")),
              (V{"3 toB b hello", "4 toD d nobody", "5 toC c for c", "7 toC2 c again"}))
        << "a listener on the ego vehicle hears its own signal once";
    EXPECT_EQ(signalsOf(h.log.find("a", "TestProbeB")), (V{"3 toB b hello", "4 toD d nobody", "5 toC c for c"}))
        << "nothing after its vehicle arrived at 6 s";
    EXPECT_EQ(signalsOf(h.log.find("a", "TestProbe")), V{});
    EXPECT_EQ(signalsOf(h.log.find("c", "TestProbe")), (V{"5 toC c for c", "7 toC2 c again"}));
    EXPECT_EQ(h.log.of("d").size(), 0u);
    for (const auto& r : h.log.records) EXPECT_EQ(r->callsAfterFinish, 0) << r->name;
}

}  // namespace
}  // namespace sbsim::services::test
