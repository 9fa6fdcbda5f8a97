// The per-step vehicle snapshot against libsumo's own getters, at every step of a real run.
#include <gtest/gtest.h>
#include <libsumo/Simulation.h>
#include <libsumo/Vehicle.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "SumoTestSupport.h"
#include "TestPrinters.h"
#include "sbsim/kernel/Simulation.h"
#include "sbsim/traffic/SumoBridge.h"
#include "sbsim/traffic/VehicleController.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::test {
namespace {

using kernel::Module;
using kernel::SignalId;
using kernel::SimTime;
using traffic::SumoBridge;
using traffic::VehicleSnapshot;

/// Listens to the bridge's signals and checks each step's snapshot against libsumo, which at
/// that moment still holds the state of the step just made.
class SnapshotChecker : public kernel::Listener {
public:
    /// Listens to the bridge's departures, arrivals and steps from now on, asking for `columns`
    /// (it checks the values a snapshot says it holds).
    SnapshotChecker(kernel::Simulation& sim, SumoBridge& bridge,
                    traffic::SnapshotColumns columns = traffic::SnapshotColumns::all())
        : sim_(sim), bridge_(bridge) {
        bridge.demandColumns(columns);
        sim.subscribe(SumoBridge::departedSignal, *this);
        sim.subscribe(SumoBridge::arrivedSignal, *this);
        sim.subscribe(SumoBridge::stepSignal, *this);
    }

    void receiveSignal(Module& source, SignalId id, std::string_view value) override {
        EXPECT_EQ(&source, &bridge_);
        if (id == SumoBridge::departedSignal) {
            announced_.push_back("departed " + std::string(value));
            ++departedTotal;
        } else if (id == SumoBridge::arrivedSignal) {
            announced_.push_back("arrived " + std::string(value));
            ++arrivedTotal;
        }
    }

    void receiveSignal(Module& source, SignalId id, const kernel::Object& value) override {
        if (id != SumoBridge::stepSignal) return;
        EXPECT_EQ(&source, &bridge_);
        const auto* snapshot = dynamic_cast<const VehicleSnapshot*>(&value);
        ASSERT_NE(snapshot, nullptr);
        EXPECT_EQ(snapshot, &bridge_.snapshot());
        ++steps;
        checkTime(*snapshot);
        checkAnnouncements();
        checkVehicles(*snapshot);
        checkIdsVersion(*snapshot);
        announced_.clear();
        lastStep = snapshot->time();
        peak = std::max<std::size_t>(peak, static_cast<std::size_t>(snapshot->size()));
        checkedVehicles += static_cast<std::size_t>(snapshot->size());
    }

    int steps = 0;
    int idsKept = 0;     // steps whose snapshot had the same vehicles as the step before
    int idsChanged = 0;  // steps in which some came or went
    int departedTotal = 0;
    int arrivedTotal = 0;
    std::size_t peak = 0;
    std::size_t checkedVehicles = 0;
    SimTime lastStep;

private:
    void checkTime(const VehicleSnapshot& snapshot) {
        const SimTime sumoNow = SimTime::fromMilliseconds(libsumo::Simulation::getCurrentTime());
        EXPECT_EQ(snapshot.time(), sumoNow);
        EXPECT_EQ(sim_.now(), sumoNow);
        EXPECT_EQ(sumoNow, bridge_.beginTime() + bridge_.stepLength() * steps);
    }

    // Departures, then arrivals, each in ascending order, all before the step signal.
    void checkAnnouncements() {
        std::vector<std::string> departed = libsumo::Simulation::getDepartedIDList();
        std::vector<std::string> arrived = libsumo::Simulation::getArrivedIDList();
        std::sort(departed.begin(), departed.end());
        std::sort(arrived.begin(), arrived.end());
        std::vector<std::string> expected;
        for (const auto& id : departed) expected.push_back("departed " + id);
        for (const auto& id : arrived) expected.push_back("arrived " + id);
        EXPECT_EQ(announced_, expected) << "at " << sim_.now().str() << " s";
    }

    // The same ids as the step before keep the version (the storyboard then skips matching
    // them); any change gives a new one.
    void checkIdsVersion(const VehicleSnapshot& s) {
        if (steps > 1) {
            if (s.ids() == lastIds_) {
                EXPECT_EQ(s.idsVersion(), lastVersion_) << "at " << sim_.now().str() << " s";
                ++idsKept;
            } else {
                EXPECT_NE(s.idsVersion(), lastVersion_) << "at " << sim_.now().str() << " s";
                ++idsChanged;
            }
        }
        lastIds_ = s.ids();
        lastVersion_ = s.idsVersion();
    }

    void checkVehicles(const VehicleSnapshot& s) {
        std::vector<std::string> sumoIds = libsumo::Vehicle::getIDList();
        std::sort(sumoIds.begin(), sumoIds.end());
        ASSERT_EQ(s.ids(), sumoIds) << "at " << sim_.now().str() << " s";
        ASSERT_EQ(s.positions().cols(), s.size());
        ASSERT_EQ(s.speeds().size(), s.size());
        for (VehicleSnapshot::Index i = 0; i < s.size(); ++i) {
            const std::string& id = s.ids()[i];
            if (i > 0) {
                EXPECT_LT(s.ids()[i - 1], id);  // strictly ascending
            }
            EXPECT_EQ(s.indexOf(id), i);
            const libsumo::TraCIPosition p = libsumo::Vehicle::getPosition(id);
            std::ostringstream diff;
            diff.precision(17);
            const auto same = [&](const char* what, const auto& mine, const auto& sumo) {
                if (mine != sumo) diff << " " << what << ": " << mine << " != " << sumo << ";";
            };
            using Col = traffic::SnapshotColumns;
            const Col has = s.columns();
            if (has.contains(Col::Position)) {
                same("x", s.positions()(0, i), p.x);
                same("y", s.positions()(1, i), p.y);
            }
            if (has.contains(Col::Speed)) same("speed", s.speeds()[i], libsumo::Vehicle::getSpeed(id));
            if (has.contains(Col::Angle)) same("angle", s.angles()[i], libsumo::Vehicle::getAngle(id));
            if (has.contains(Col::Acceleration)) {
                same("acceleration", s.accelerations()[i], libsumo::Vehicle::getAcceleration(id));
            }
            if (has.contains(Col::Size)) {
                same("length", s.lengths()[i], libsumo::Vehicle::getLength(id));
                same("width", s.widths()[i], libsumo::Vehicle::getWidth(id));
            }
            if (has.contains(Col::MaxSpeed)) same("maxSpeed", s.maxSpeeds()[i], libsumo::Vehicle::getMaxSpeed(id));
            if (has.contains(Col::Lane)) {
                same("road", s.roadId(i), libsumo::Vehicle::getRoadID(id));
                same("lane", s.laneId(i), libsumo::Vehicle::getLaneID(id));
            }
            if (has.contains(Col::Type)) {
                // A command on one vehicle makes SUMO copy its type as "<type>@<id>"; the snapshot
                // keeps the type the vehicle departed with.
                std::string type = libsumo::Vehicle::getTypeID(id);
                if (const std::string copy = "@" + id; type.ends_with(copy)) type.resize(type.size() - copy.size());
                same("type", s.typeId(i), type);
            }
            // One message per vehicle and step, not one per field: a systematic error stays readable.
            EXPECT_TRUE(diff.str().empty()) << id << " at " << sim_.now().str() << " s:" << diff.str();
        }
        EXPECT_FALSE(s.indexOf("no-such-vehicle").has_value());
        EXPECT_FALSE(s.indexOf("veh").has_value());  // a prefix of every id
    }

    kernel::Simulation& sim_;
    SumoBridge& bridge_;
    std::vector<std::string> announced_;
    std::vector<std::string> lastIds_;
    std::uint64_t lastVersion_ = 0;
};

class SnapshotTest : public testing::TestWithParam<unsigned> {};

TEST_P(SnapshotTest, MatchesLibsumoAtEveryStep) {
    traffic::SumoSettings settings = scenarioSettings();
    kernel::Simulation sim(0, GetParam());
    auto& bridge = sim.emplaceModule<SumoBridge>(settings);
    SnapshotChecker checker(sim, bridge);

    bridge.load();
    ASSERT_TRUE(bridge.loaded());
    EXPECT_EQ(bridge.beginTime(), SimTime::zero());
    EXPECT_EQ(bridge.stepLength(), sec(1));
    EXPECT_EQ(bridge.endTime(), sec(120));  // from the configuration
    const libsumo::TraCIPositionVector boundary = libsumo::Simulation::getNetBoundary();
    ASSERT_EQ(boundary.value.size(), 2u);
    EXPECT_EQ(bridge.netBoundary()(0, 0), boundary.value[0].x);
    EXPECT_EQ(bridge.netBoundary()(1, 0), boundary.value[0].y);
    EXPECT_EQ(bridge.netBoundary()(0, 1), boundary.value[1].x);
    EXPECT_EQ(bridge.netBoundary()(1, 1), boundary.value[1].y);
    EXPECT_GT(bridge.netBoundary()(0, 1), bridge.netBoundary()(0, 0));

    EXPECT_EQ(sim.run(), kernel::Simulation::StopReason::Requested);
    EXPECT_EQ(bridge.endReason(), SumoBridge::EndReason::EndTime);
    EXPECT_EQ(checker.steps, 120);
    EXPECT_EQ(bridge.steps(), 120u);
    EXPECT_EQ(checker.lastStep, sec(120));
    EXPECT_EQ(sim.now(), sec(120));
    EXPECT_EQ(static_cast<std::uint64_t>(checker.departedTotal), bridge.vehiclesSeen());
    EXPECT_EQ(checker.peak, bridge.peakRunning());
    // Not vacuous: vehicles came and went, and many vehicle-steps were compared.
    EXPECT_GT(checker.departedTotal, 100);
    EXPECT_GT(checker.arrivedTotal, 10);
    EXPECT_GT(checker.checkedVehicles, 2000u);
    EXPECT_GT(checker.idsChanged, 10);
    EXPECT_GT(checker.idsKept, 0);
    sim.finish();
    // Still loaded: other modules' finish() may ask SUMO about their vehicles; the destructor closes it.
    EXPECT_TRUE(bridge.loaded());
    EXPECT_TRUE(libsumo::Simulation::isLoaded());
}

INSTANTIATE_TEST_SUITE_P(Threads, SnapshotTest, testing::Values(1u, 0u),
                         [](const testing::TestParamInfo<unsigned>& info) {
                             return info.param == 0   ? std::string("AllCores")
                                    : info.param == 1 ? std::string("OneThread")
                                                      : std::to_string(info.param) + "Threads";
                         });

// Enough vehicles (over 3 x 512) for the snapshot reads to be split over threads.
TEST(SnapshotDense, ParallelReadsMatchLibsumo) {
    traffic::SumoSettings settings = scenarioSettings();
    settings.sumocfg = denseScenarioConfig();
    settings.end = sec(110);
    kernel::Simulation sim(0, 4);
    auto& bridge = sim.emplaceModule<SumoBridge>(settings);
    SnapshotChecker checker(sim, bridge);
    sim.run();
    EXPECT_EQ(checker.steps, 110);
    EXPECT_GE(checker.peak, 3u * 512u);
    sim.finish();
}

// The snapshot reads only the values someone asked for; a reader that comes later gets the
// constant values (type, size, max speed) of the vehicles already running at once.
TEST(SnapshotColumns, OnlyWhatWasAskedForIsReadAndLateReadersGetEverything) {
    using Col = traffic::SnapshotColumns;
    traffic::SumoSettings settings = scenarioSettings();
    settings.end = sec(40);
    kernel::Simulation sim(0, 2);
    auto& bridge = sim.emplaceModule<SumoBridge>(settings);
    SnapshotChecker checker(sim, bridge, Col::none());
    sim.run(sec(10));
    EXPECT_TRUE(bridge.snapshot().columns().empty()) << bridge.snapshot().columns().str();
    EXPECT_GT(bridge.snapshot().size(), 0) << "ids are always there";
    bridge.demandColumns(Col::Speed);
    sim.run(sec(20));
    EXPECT_EQ(bridge.snapshot().columns(), Col::Speed);
    bridge.demandColumns({Col::Type, Col::Size, Col::Lane});
    sim.run();
    EXPECT_EQ(bridge.snapshot().columns(), (Col{Col::Speed, Col::Type, Col::Size, Col::Lane}));
    EXPECT_EQ(bridge.snapshot().columns().str(), "speed|lane|size|type");
    EXPECT_EQ(checker.steps, 40);
    sim.finish();
}

// Commands change what the snapshot must show: max speeds set through VehicleController, and
// speeds forced by setSpeed / slowDown (acceleration is derived from speeds, max speed is re-read
// only after a change). Sub-second steps make the derivation divide by 0.1 s.
TEST(SnapshotCommanded, MatchesLibsumoWhileVehiclesAreCommanded) {
    class Commander : public kernel::Listener {
    public:
        explicit Commander(traffic::MaxSpeedListener& listener) : listener_(listener) {}
        void receiveSignal(kernel::Module&, kernel::SignalId, const kernel::Object& value) override {
            const auto& s = dynamic_cast<const traffic::VehicleSnapshot&>(value);
            ++steps;
            for (traffic::VehicleSnapshot::Index i = 0; i < s.size(); ++i) {
                traffic::VehicleController v(s.ids()[i], &listener_);
                switch ((steps + i) % 37) {
                    case 0:
                        v.setMaxSpeed(3.0 + (i % 5));
                        ++commands;
                        break;
                    case 7:
                        v.setSpeed(0.0);
                        ++commands;
                        break;
                    case 13:
                        v.setSpeed(-1.0);
                        ++commands;
                        break;
                    case 21:
                        v.slowDown(1.0, 2.0);
                        ++commands;
                        break;
                    case 29:
                        v.setMaxSpeed(40.0);
                        ++commands;
                        break;
                    default:
                        break;
                }
            }
        }
        int steps = 0;
        int commands = 0;

    private:
        traffic::MaxSpeedListener& listener_;
    };
    traffic::SumoSettings settings = scenarioSettings();
    settings.extraOptions = {"--step-length", "0.1"};
    settings.end = sec(60);
    kernel::Simulation sim;
    auto& bridge = sim.emplaceModule<SumoBridge>(settings);
    SnapshotChecker checker(sim, bridge);
    Commander commander(bridge.maxSpeedListener());
    // The checker, subscribed first, checks step k's snapshot; then the commander commands for k+1.
    sim.subscribe(SumoBridge::stepSignal, commander);
    sim.run();
    EXPECT_EQ(checker.steps, 600);
    EXPECT_GT(commander.commands, 1000);
    EXPECT_GT(checker.checkedVehicles, 5000u);
    sim.finish();
}

/// Every value of every step of a run, as text with exact (hex) doubles.
std::vector<std::string> recordRun(std::int64_t seed, unsigned threads) {
    struct Recorder : kernel::Listener {
        std::vector<std::string> lines;
        void receiveSignal(Module&, SignalId, const kernel::Object& value) override {
            const auto& s = dynamic_cast<const VehicleSnapshot&>(value);
            std::ostringstream out;
            out << std::hexfloat << s.time().str();
            for (VehicleSnapshot::Index i = 0; i < s.size(); ++i) {
                out << " " << s.ids()[i] << " " << s.positions()(0, i) << " " << s.positions()(1, i) << " "
                    << s.speeds()[i] << " " << s.angles()[i] << " " << s.accelerations()[i] << " " << s.laneId(i);
            }
            lines.push_back(out.str());
        }
    } recorder;
    traffic::SumoSettings settings = scenarioSettings();
    settings.seed = seed;
    settings.end = sec(40);
    kernel::Simulation sim(0, threads);
    sim.emplaceModule<SumoBridge>(settings).demandColumns(traffic::SnapshotColumns::all());
    sim.subscribe(SumoBridge::stepSignal, recorder);
    sim.run();
    sim.finish();
    return recorder.lines;
}

// Also shows that libsumo can be loaded and closed several times in one process.
TEST(SnapshotRuns, AreReproducibleAcrossReloads) {
    const auto first = recordRun(7, 1);
    ASSERT_EQ(first.size(), 40u);
    EXPECT_EQ(recordRun(7, 1), first);
    EXPECT_EQ(recordRun(7, 3), first);
    EXPECT_NE(recordRun(8, 1), first);  // the seed reaches SUMO
}

}  // namespace
}  // namespace sbsim::test
