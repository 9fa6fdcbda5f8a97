// SumoBridge as a kernel module: loading, errors, end time, step timing among other events.
#include <gtest/gtest.h>

#include <libsumo/Simulation.h>
#include <unistd.h>
#include <optional>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "SumoTestSupport.h"
#include "TestPrinters.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/traffic/NetworkController.h"
#include "sbsim/traffic/SumoBridge.h"
#include "sbsim/traffic/SumoRouteChecks.h"

namespace sbsim::test {
namespace {

namespace fs = std::filesystem;
using kernel::SimTime;
using kernel::Simulation;
using traffic::SumoBridge;
using traffic::SumoLoadError;

/// A scratch folder for configurations the test writes.
class ScratchDir {
public:
    ScratchDir() {
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("sbsim-test-" + std::string(info->name()) + "-" + std::to_string(static_cast<long>(::getpid())));
        fs::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    fs::path write(const std::string& name, const std::string& text) const {
        std::ofstream(path_ / name) << text;
        return path_ / name;
    }

private:
    fs::path path_;
};

/// Counts the steps and remembers their times.
struct StepLog : kernel::Listener {
    std::vector<SimTime> times;
    void receiveSignal(kernel::Module&, kernel::SignalId id, const kernel::Object&) override {
        if (id == SumoBridge::stepSignal)
            times.push_back(SimTime::fromMilliseconds(libsumo::Simulation::getCurrentTime()));
    }
};

TEST(SumoBridge, LoadErrorCarriesSumosMessage) {
    ScratchDir dir;
    const fs::path cfg = dir.write(
        "broken.sumocfg", "<configuration><input><net-file value=\"missing.net.xml\"/></input></configuration>\n");
    traffic::SumoSettings settings;
    settings.sumocfg = cfg;
    SumoBridge bridge(settings);
    try {
        bridge.load();
        FAIL() << "loaded a configuration without its network";
    } catch (const SumoLoadError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("missing.net.xml"), std::string::npos) << what;
        EXPECT_NE(what.find("not accessible"), std::string::npos) << what;  // SUMO's words, not a generic one
        EXPECT_EQ(what.find("Error:"), std::string::npos) << what;          // the prefix is folded away
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;              // one line
    }
    EXPECT_FALSE(bridge.loaded());
    EXPECT_FALSE(libsumo::Simulation::isLoaded());
}

TEST(SumoBridge, MissingConfigurationIsALoadError) {
    traffic::SumoSettings settings;
    settings.sumocfg = "/nonexistent/sbsim/none.sumocfg";
    SumoBridge bridge(settings);
    try {
        bridge.load();
        FAIL() << "loaded a configuration that does not exist";
    } catch (const SumoLoadError& e) {
        EXPECT_NE(std::string(e.what()).find("none.sumocfg"), std::string::npos) << e.what();
    }
}

TEST(SumoBridge, BadOptionIsALoadError) {
    traffic::SumoSettings settings = scenarioSettings();
    settings.extraOptions = {"--no-such-option", "1"};
    SumoBridge bridge(settings);
    try {
        bridge.load();
        FAIL() << "SUMO accepted an unknown option";
    } catch (const SumoLoadError& e) {
        EXPECT_NE(std::string(e.what()).find("no-such-option"), std::string::npos) << e.what();
    }
}

TEST(SumoBridge, LoadsAfterAFailedLoad) {
    {
        traffic::SumoSettings broken;
        broken.sumocfg = "/nonexistent/sbsim/none.sumocfg";
        SumoBridge bridge(broken);
        EXPECT_THROW(bridge.load(), SumoLoadError);
    }
    Simulation sim;
    auto& bridge = sim.emplaceModule<SumoBridge>(scenarioSettings());
    ASSERT_NO_THROW(bridge.load());
    EXPECT_TRUE(bridge.loaded());
    EXPECT_EQ(sim.run(sec(5)), Simulation::StopReason::TimeLimit);
    EXPECT_EQ(bridge.steps(), 5u);
}

TEST(SumoBridge, LoadIsIdempotentAndTheDestructorCloses) {
    {
        SumoBridge bridge(scenarioSettings());
        bridge.load();
        bridge.load();
        EXPECT_TRUE(libsumo::Simulation::isLoaded());
    }
    EXPECT_FALSE(libsumo::Simulation::isLoaded());
}

TEST(SumoBridge, UserOptionsOverrideTheDefaults) {
    // --no-step-log is one of sbsim's defaults; SUMO refuses an option given twice.
    traffic::SumoSettings settings = scenarioSettings();
    settings.extraOptions = {"--no-step-log", "true", "--no-warnings", "true"};
    SumoBridge bridge(settings);
    EXPECT_NO_THROW(bridge.load());
}

/// The switch sbsim turns off during closures is the one SUMO sets from --ignore-route-errors.
TEST(SumoBridge, RouteChecksAreSumosOwnSwitch) {
    for (const bool ignore : {false, true, false}) {
        traffic::SumoSettings settings = scenarioSettings();
        if (ignore) settings.extraOptions = {"--ignore-route-errors", "true"};
        SumoBridge bridge(settings);
        bridge.load();
        EXPECT_EQ(libsumo::Simulation::getOption("ignore-route-errors"), ignore ? "true" : "false");
        EXPECT_EQ(traffic::sumoRouteChecks(), !ignore);
        traffic::setSumoRouteChecks(ignore);
        EXPECT_EQ(traffic::sumoRouteChecks(), ignore);
    }
}

struct EndCase {
    double end;
    int steps;
};

class SumoBridgeEnd : public testing::TestWithParam<EndCase> {};

TEST_P(SumoBridgeEnd, StopsAfterTheStepReachingTheEnd) {
    traffic::SumoSettings settings = scenarioSettings();
    settings.end = sec(GetParam().end);
    Simulation sim;
    auto& bridge = sim.emplaceModule<SumoBridge>(settings);
    StepLog log;
    sim.subscribe(SumoBridge::stepSignal, log);
    EXPECT_EQ(sim.run(), Simulation::StopReason::Requested);
    EXPECT_EQ(bridge.endReason(), SumoBridge::EndReason::EndTime);
    EXPECT_EQ(bridge.endTime(), sec(GetParam().end));
    EXPECT_EQ(bridge.steps(), static_cast<std::uint64_t>(GetParam().steps));
    ASSERT_EQ(log.times.size(), static_cast<std::size_t>(GetParam().steps));
    EXPECT_EQ(log.times.back(), sec(GetParam().steps));
    EXPECT_EQ(sim.now(), sec(GetParam().steps));
    EXPECT_TRUE(sim.futureEvents().empty());  // no step left behind
}

INSTANTIATE_TEST_SUITE_P(Settings, SumoBridgeEnd,
                         testing::Values(EndCase{30, 30}, EndCase{30.5, 31}, EndCase{1, 1}, EndCase{180, 180}),
                         [](const testing::TestParamInfo<EndCase>& info) {
                             std::string name = "End" + SimTime::fromSeconds(info.param.end).str();
                             for (char& c : name) {
                                 if (c == '.') c = '_';
                             }
                             return name;
                         });

TEST(SumoBridge, StopsWhenNoVehicleIsLeft) {
    traffic::SumoSettings settings = scenarioSettings();
    settings.end = sec(3600);  // far beyond the last arrival
    Simulation sim;
    auto& bridge = sim.emplaceModule<SumoBridge>(settings);
    int minExpectedAtLastStep = -1;
    struct LastStep : kernel::Listener {
        int* out;
        void receiveSignal(kernel::Module&, kernel::SignalId, const kernel::Object&) override {
            *out = libsumo::Simulation::getMinExpectedNumber();
        }
    } last;
    last.out = &minExpectedAtLastStep;
    sim.subscribe(SumoBridge::stepSignal, last);
    EXPECT_EQ(sim.run(), Simulation::StopReason::Requested);
    EXPECT_EQ(bridge.endReason(), SumoBridge::EndReason::NoMoreVehicles);
    EXPECT_EQ(minExpectedAtLastStep, 0);
    EXPECT_TRUE(bridge.snapshot().empty());
    EXPECT_LT(sim.now(), sec(3600));
    EXPECT_GT(sim.now(), sec(120));
    EXPECT_EQ(bridge.vehiclesSeen(), 120u);  // every vehicle of the route file
    EXPECT_TRUE(sim.futureEvents().empty());
}

TEST(SumoBridge, EndAtTheBeginTimeRunsNoStep) {
    // Another module with an endless timer: the run must still end, at once.
    class Beacon : public kernel::Module {
    public:
        Beacon() : Module("beacon") {}
        void initialize() override { scheduleAt(SimTime::fromMilliseconds(100), timer_); }
        void handleMessage(kernel::Message&) override { scheduleAfter(SimTime::fromMilliseconds(100), timer_); }

    private:
        kernel::Message timer_{"beacon"};
    };
    traffic::SumoSettings settings = scenarioSettings();
    settings.end = sec(0);  // the begin time: no step has to run to reach it
    Simulation sim;
    auto& bridge = sim.emplaceModule<SumoBridge>(settings);
    sim.emplaceModule<Beacon>();
    EXPECT_EQ(sim.run(sec(1000)), Simulation::StopReason::Requested);
    EXPECT_EQ(bridge.steps(), 0u);
    EXPECT_EQ(bridge.endReason(), SumoBridge::EndReason::EndTime);
    EXPECT_EQ(sim.eventCount(), 1u);  // only the end-of-run event itself
}

TEST(SumoBridge, EventsDueAtTheEndTimeStillHappen) {
    // A timer at exactly the end time comes after that step (steps go first) but before the stop.
    class AtEnd : public kernel::Module {
    public:
        AtEnd() : Module("at end") {}
        void initialize() override { scheduleAt(sec(30), timer_); }
        void handleMessage(kernel::Message&) override { fired = simTime(); }
        std::optional<SimTime> fired;

    private:
        kernel::Message timer_{"at end"};
    };
    traffic::SumoSettings settings = scenarioSettings();
    settings.end = sec(30);
    Simulation sim;
    auto& bridge = sim.emplaceModule<SumoBridge>(settings);
    auto& atEnd = sim.emplaceModule<AtEnd>();
    EXPECT_EQ(sim.run(), Simulation::StopReason::Requested);
    EXPECT_EQ(bridge.steps(), 30u);
    ASSERT_TRUE(atEnd.fired.has_value());
    EXPECT_EQ(*atEnd.fired, sec(30));
}

TEST(SumoBridge, SubSecondStepsKeepExactTime) {
    traffic::SumoSettings settings = scenarioSettings();
    settings.extraOptions = {"--step-length", "0.1"};
    settings.end = sec(12.3);
    Simulation sim;
    auto& bridge = sim.emplaceModule<SumoBridge>(settings);
    StepLog log;
    sim.subscribe(SumoBridge::stepSignal, log);
    sim.run();
    EXPECT_EQ(bridge.stepLength(), SimTime::fromMilliseconds(100));
    ASSERT_EQ(log.times.size(), 123u);
    for (std::size_t i = 0; i < log.times.size(); ++i) {
        ASSERT_EQ(log.times[i], SimTime::fromMilliseconds(100 * static_cast<SimTime::rep>(i + 1))) << i;
    }
    EXPECT_EQ(sim.now(), sec(12.3));
}

TEST(SumoBridge, OtherEventsInterleaveWithSteps) {
    // At each step, a module asks for an event 1 ms later (a radio latency): it runs between two
    // steps. Its 1 s timer, due at the same times as the steps, runs after them.
    class Probe : public kernel::Module, public kernel::Listener {
    public:
        Probe() : Module("probe") {}
        std::vector<std::string> trace;
        void initialize() override { scheduleAt(SimTime::fromSeconds(1), tick_); }
        void receiveSignal(kernel::Module&, kernel::SignalId id, const kernel::Object&) override {
            if (id != SumoBridge::stepSignal) return;
            trace.push_back("step " + simTime().str() + " sumo " + sumoNow());
            scheduleAfter(SimTime::fromMilliseconds(1), latency_);
        }
        void handleMessage(kernel::Message& msg) override {
            trace.push_back(msg.name() + " " + simTime().str() + " sumo " + sumoNow());
            if (&msg == &tick_) scheduleAfter(SimTime::fromSeconds(1), tick_);
        }

    private:
        static std::string sumoNow() { return SimTime::fromMilliseconds(libsumo::Simulation::getCurrentTime()).str(); }
        kernel::Message tick_{"tick"};
        kernel::Message latency_{"latency"};
    };
    Simulation sim;
    sim.emplaceModule<SumoBridge>(scenarioSettings());
    auto& probe = sim.emplaceModule<Probe>();
    sim.subscribe(SumoBridge::stepSignal, probe);
    EXPECT_EQ(sim.run(sec(3)), Simulation::StopReason::TimeLimit);
    EXPECT_EQ(probe.trace,
              (std::vector<std::string>{"step 1 sumo 1", "tick 1 sumo 1", "latency 1.001 sumo 1", "step 2 sumo 2",
                                        "tick 2 sumo 2", "latency 2.001 sumo 2", "step 3 sumo 3", "tick 3 sumo 3"}));
}

TEST(SumoBridge, AVehicleACommandRemovedArrivesAtTheNextStep) {
    // libsumo lists a vehicle removed between two steps only until the next step begins: the
    // network controller tells the bridge, which reports it then, once, like SUMO's own arrivals.
    // One removed in the step it departed (a closure's case) and one that has run for a while.
    class Remover : public kernel::Listener {
    public:
        explicit Remover(SumoBridge& bridge) : network_(&bridge), bridge_(bridge) {}
        std::vector<std::string> removed, arrivedAfter;
        void receiveSignal(kernel::Module&, kernel::SignalId id, std::string_view value) override {
            if (id == SumoBridge::departedSignal && removed.empty()) fresh_ = std::string(value);
            if (id == SumoBridge::arrivedSignal) arrived_.emplace_back(value);
        }
        void receiveSignal(kernel::Module&, kernel::SignalId id, const kernel::Object&) override {
            if (id != SumoBridge::stepSignal) return;
            for (const std::string& a : arrived_) {
                if (std::find(removed.begin(), removed.end(), a) != removed.end()) arrivedAfter.push_back(a);
                EXPECT_FALSE(bridge_.snapshot().indexOf(a)) << a << " still in the snapshot";
            }
            arrived_.clear();
            if (removed.empty() && fresh_) {
                removed.push_back(*fresh_);  // departed in this very step
                network_.removeVehicle(*fresh_);
            } else if (removed.size() == 1 && bridge_.snapshot().size() > 1 && libsumo::Simulation::getTime() >= 20) {
                removed.push_back(bridge_.snapshot().ids().back());  // running for a while
                network_.removeVehicle(removed.back());
            }
        }

    private:
        traffic::NetworkController network_;
        SumoBridge& bridge_;
        std::optional<std::string> fresh_;
        std::vector<std::string> arrived_;
    };
    traffic::SumoSettings settings = scenarioSettings();
    settings.end = sec(40);
    Simulation sim;
    auto& bridge = sim.emplaceModule<SumoBridge>(settings);
    Remover remover(bridge);
    sim.subscribe(SumoBridge::departedSignal, remover);
    sim.subscribe(SumoBridge::arrivedSignal, remover);
    sim.subscribe(SumoBridge::stepSignal, remover);
    sim.run();
    ASSERT_EQ(remover.removed.size(), 2u);
    EXPECT_NE(remover.removed[0], remover.removed[1]);
    EXPECT_EQ(remover.arrivedAfter, remover.removed);  // each once, at the step after its removal
}

}  // namespace
}  // namespace sbsim::test
